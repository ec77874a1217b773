#include "esi/xml/identity_scan.hpp"

#include <algorithm>
#include <cstring>

#include "esi/encoding.hpp"
#include "esi/number.hpp"

namespace esi {

namespace {

// Appends `text` with the five predefined entities and character references decoded.
void append_decoded(std::string& out, std::string_view text) {
    while (!text.empty()) {
        const std::size_t amp = text.find('&');
        out.append(text.substr(0, amp));
        if (amp == std::string_view::npos) return;
        text.remove_prefix(amp);
        const std::size_t semi = text.find(';');
        if (semi == std::string_view::npos || semi > 12) {
            out += '&';
            text.remove_prefix(1);
            continue;
        }
        const std::string_view entity = text.substr(1, semi - 1);
        text.remove_prefix(semi + 1);
        if (entity == "lt") out += '<';
        else if (entity == "gt") out += '>';
        else if (entity == "amp") out += '&';
        else if (entity == "quot") out += '"';
        else if (entity == "apos") out += '\'';
        else if (entity.size() > 1 && entity[0] == '#') {
            const bool hex = entity[1] == 'x';
            std::uint32_t cp = 0;
            for (char c : entity.substr(hex ? 2 : 1)) {
                const int digit = c >= '0' && c <= '9' ? c - '0'
                                  : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                                  : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                                : -1;
                if (digit < 0 || cp > 0x10FFFF) {
                    cp = 0xFFFD;
                    break;
                }
                cp = cp * (hex ? 16 : 10) + static_cast<std::uint32_t>(digit);
            }
            if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) cp = 0xFFFD;
            append_utf8(out, cp);
        } else {
            out += '&';
            out.append(entity);
            out += ';';
        }
    }
}

std::optional<std::uint32_t> number_value(std::string_view text) {
    const ParsedNumber n = parse_number(text);
    if (!n.ok()) return std::nullopt;
    const auto v = n.value.as_uint64();
    if (!v || *v > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<std::uint32_t>(*v);
}

// An attribute value as the full reader sees it: "&#35;x1003" is "#x1003".
std::string decoded(std::string_view raw) {
    std::string out;
    append_decoded(out, raw);
    return out;
}

bool is_name_end(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '/' || c == '>'; }

struct Attribute {
    std::string_view name;
    std::string_view value;  // raw, entities not decoded
};

struct Tag {
    std::string_view name;
    std::vector<Attribute> attributes;
    bool self_closing = false;
    std::size_t end = 0;  // offset after '>'
};

class Scanner {
public:
    explicit Scanner(std::string_view text) : text_(text) {}

    IdentityScan run() {
        IdentityScan result;
        std::size_t pos = 0;
        while (error_.empty()) {
            const std::size_t lt = text_.find('<', pos);
            if (lt == std::string_view::npos) break;
            pos = markup(lt, result);
        }
        if (error_.empty() && !stack_.empty()) error_ = "unclosed element <" + std::string(stack_.back()) + ">";
        result.error = error_;
        return result;
    }

private:
    // Handles the markup at `lt` (text_[lt] == '<'); returns where to go on.
    std::size_t markup(std::size_t lt, IdentityScan& result) {
        const std::string_view rest = text_.substr(lt);
        if (rest.starts_with("<!--")) return skip_past(lt + 4, "-->", "unterminated comment");
        if (rest.starts_with("<![CDATA[")) return skip_past(lt + 9, "]]>", "unterminated CDATA section");
        if (rest.starts_with("<?")) return skip_past(lt + 2, "?>", "unterminated processing instruction");
        if (rest.starts_with("<!")) return skip_declaration(lt);
        if (rest.starts_with("</")) return end_tag(lt, result);
        return start_tag(lt, result);
    }

    std::size_t skip_past(std::size_t from, std::string_view terminator, const char* message) {
        const std::size_t at = text_.find(terminator, from);
        if (at == std::string_view::npos) {
            error_ = message;
            return text_.size();
        }
        return at + terminator.size();
    }

    // <!DOCTYPE …> with an optional internal subset in brackets.
    std::size_t skip_declaration(std::size_t lt) {
        const std::size_t close = text_.find('>', lt);
        const std::size_t bracket = text_.find('[', lt);
        if (bracket != std::string_view::npos && bracket < close) return skip_past(bracket, "]>", "unterminated DOCTYPE");
        if (close == std::string_view::npos) error_ = "unterminated declaration";
        return close == std::string_view::npos ? text_.size() : close + 1;
    }

    std::size_t end_tag(std::size_t lt, IdentityScan& result) {
        std::size_t p = lt + 2;
        const std::size_t name_start = p;
        while (p < text_.size() && !is_name_end(text_[p])) ++p;
        const std::string_view name = text_.substr(name_start, p - name_start);
        const std::size_t close = text_.find('>', p);
        if (close == std::string_view::npos) {
            error_ = "unterminated end tag";
            return text_.size();
        }
        if (stack_.empty() || stack_.back() != name) {
            error_ = "mismatched end tag </" + std::string(name) + ">";
            return text_.size();
        }
        stack_.pop_back();
        if (device_ && stack_.size() == device_depth_) finish_device(result);
        return close + 1;
    }

    std::optional<Tag> read_tag(std::size_t lt) {
        Tag tag;
        std::size_t p = lt + 1;
        const std::size_t name_start = p;
        while (p < text_.size() && !is_name_end(text_[p])) ++p;
        tag.name = text_.substr(name_start, p - name_start);
        for (;;) {
            while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t' || text_[p] == '\r' || text_[p] == '\n')) ++p;
            if (p >= text_.size()) break;
            if (text_[p] == '>') {
                tag.end = p + 1;
                return tag;
            }
            if (text_[p] == '/') {
                if (p + 1 < text_.size() && text_[p + 1] == '>') {
                    tag.self_closing = true;
                    tag.end = p + 2;
                    return tag;
                }
                break;
            }
            const std::size_t attr_start = p;
            while (p < text_.size() && text_[p] != '=' && text_[p] != '>' && text_[p] != ' ' && text_[p] != '\t' &&
                   text_[p] != '\r' && text_[p] != '\n')
                ++p;
            const std::string_view attr_name = text_.substr(attr_start, p - attr_start);
            while (p < text_.size() && text_[p] != '=' && text_[p] != '>') ++p;
            if (p >= text_.size() || text_[p] != '=') break;
            ++p;
            while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t' || text_[p] == '\r' || text_[p] == '\n')) ++p;
            if (p >= text_.size() || (text_[p] != '"' && text_[p] != '\'')) break;
            const char quote = text_[p];
            const std::size_t value_end = text_.find(quote, p + 1);
            if (value_end == std::string_view::npos) break;
            tag.attributes.push_back({attr_name, text_.substr(p + 1, value_end - p - 1)});
            p = value_end + 1;
        }
        error_ = "malformed start tag <" + std::string(tag.name) + ">";
        return std::nullopt;
    }

    static std::string_view attribute(const Tag& tag, std::string_view name) {
        for (const Attribute& a : tag.attributes)
            if (a.name == name) return a.value;
        return {};
    }

    // The character data of a leaf element starting at `from` (CDATA sections included, comments
    // skipped, entities decoded), trimmed; stops at the next tag.
    std::string leaf_text(std::size_t from) {
        std::string out;
        std::size_t p = from;
        while (p < text_.size()) {
            const std::size_t lt = text_.find('<', p);
            append_decoded(out, text_.substr(p, lt == std::string_view::npos ? std::string_view::npos : lt - p));
            if (lt == std::string_view::npos) break;
            const std::string_view rest = text_.substr(lt);
            if (rest.starts_with("<![CDATA[")) {
                const std::size_t end = text_.find("]]>", lt + 9);
                if (end == std::string_view::npos) break;
                out.append(text_.substr(lt + 9, end - lt - 9));
                p = end + 3;
            } else if (rest.starts_with("<!--")) {
                const std::size_t end = text_.find("-->", lt + 4);
                if (end == std::string_view::npos) break;
                p = end + 3;
            } else {
                break;
            }
        }
        return std::string(trim(out));
    }

    bool parent_is(std::string_view name, std::size_t up = 0) const {
        return stack_.size() > up && stack_[stack_.size() - 1 - up] == name;
    }

    std::size_t start_tag(std::size_t lt, IdentityScan& result) {
        const std::optional<Tag> tag = read_tag(lt);
        if (!tag) return text_.size();
        if (device_ && stack_.size() == device_depth_ + 1) {
            // A child of Device: Type, HideType, AlternativeType, SubDevice and Name lead its
            // content (ETG.2000 DeviceType); once something else starts, the rest is skipped.
            if (tag->name == "Type") {
                have_type_ = true;
                device_->product_code = number_value(decoded(attribute(*tag, "ProductCode")));
                device_->revision_no = number_value(decoded(attribute(*tag, "RevisionNo")));
                if (!tag->self_closing) device_->type = leaf_text(tag->end);
            } else if (tag->name == "HideType") {
                hides_.push_back({number_value(decoded(attribute(*tag, "ProductCode"))),
                                  number_value(decoded(attribute(*tag, "RevisionNo")))});
            } else if (tag->name == "Name") {
                const std::string_view lcid = attribute(*tag, "LcId");
                const bool english = trim(lcid) == "1033";
                if (!tag->self_closing && (!have_name_ || (english && !english_name_))) {
                    device_->name = leaf_text(tag->end);
                    have_name_ = true;
                    english_name_ = english;
                }
            } else if (have_type_ && tag->name != "HideType" && tag->name != "AlternativeType" && tag->name != "SubDevice") {
                // (A file that writes Type late, against the schema's order, is read on
                // element by element until its Type is found.)
                return skip_device_rest(lt, result);
            }
        } else if (tag->name == "Id" && parent_is("Vendor") && parent_is("EtherCATInfo", 1) && !tag->self_closing) {
            vendor_id_ = number_value(leaf_text(tag->end));
        } else if (tag->name == "Name" && parent_is("Vendor") && parent_is("EtherCATInfo", 1) && !tag->self_closing) {
            const bool english = trim(attribute(*tag, "LcId")) == "1033";
            if (!have_vendor_name_ || (english && !english_vendor_name_)) {
                vendor_name_ = leaf_text(tag->end);
                have_vendor_name_ = true;
                english_vendor_name_ = english;
            }
        } else if (tag->name == "EtherCATInfo") {
            vendor_id_.reset();
            vendor_name_.clear();
            have_vendor_name_ = english_vendor_name_ = false;
        } else if (tag->name == "Device" && !device_ && parent_is("Devices") && parent_is("Descriptions", 1)) {
            device_ = ScannedDevice{};
            device_->offset = lt;
            device_->pos = position_of(lt);
            device_->ordinal = ordinal_++;
            device_depth_ = stack_.size();
            have_name_ = english_name_ = have_type_ = false;
            hides_.clear();
            if (tag->self_closing) {
                finish_device(result);
                return tag->end;
            }
        }
        if (!tag->self_closing) stack_.push_back(tag->name);
        return tag->end;
    }

    // Jumps to the Device's end tag: nothing after its leading elements is needed, and a
    // Device's content (Dictionary, PDOs) is most of an ESI file. Only comments, CDATA sections
    // and Device tags matter on the way (Info/Electrical/EtherCATp holds Device elements of its
    // own).
    std::size_t skip_device_rest(std::size_t from, IdentityScan& result) {
        std::size_t depth = 1;
        std::size_t p = from;
        while (error_.empty()) {
            const std::size_t lt = text_.find('<', p);
            if (lt == std::string_view::npos) {
                error_ = "unterminated <Device>";
                return text_.size();
            }
            const std::string_view rest = text_.substr(lt);
            if (rest.starts_with("<!--")) {
                p = skip_past(lt + 4, "-->", "unterminated comment");
            } else if (rest.starts_with("<![CDATA[")) {
                p = skip_past(lt + 9, "]]>", "unterminated CDATA section");
            } else if (rest.starts_with("</Device>")) {
                p = lt + 9;
                if (--depth == 0) break;
            } else if (rest.starts_with("<Device") && rest.size() > 7 && is_name_end(rest[7])) {
                const std::size_t close = text_.find('>', lt);
                if (close == std::string_view::npos) {
                    error_ = "unterminated start tag <Device>";
                    return text_.size();
                }
                if (text_[close - 1] != '/') ++depth;
                p = close + 1;
            } else {
                p = lt + 1;
            }
        }
        stack_.resize(device_depth_);
        finish_device(result);
        return p;
    }

    void finish_device(IdentityScan& result) {
        device_->vendor_id = vendor_id_;
        device_->vendor_name = vendor_name_;
        // A HideType without ProductCode names a revision of the device's own product.
        for (HiddenIdentity& h : hides_)
            if (!h.product_code) h.product_code = device_->product_code;
        device_->hides = std::move(hides_);
        hides_.clear();
        result.devices.push_back(std::move(*device_));
        device_.reset();
    }

    // Line and column (code points) of an offset; offsets arrive in increasing order.
    SourcePos position_of(std::size_t offset) {
        const char* base = text_.data();
        for (const char* p = base + counted_; p < base + offset;) {
            const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(base + offset - p));
            if (!nl) break;
            ++line_;
            p = static_cast<const char*>(nl) + 1;
            line_start_ = static_cast<std::size_t>(p - base);
        }
        counted_ = offset;
        std::uint32_t column = 1;
        for (std::size_t i = line_start_; i < offset; ++i)
            if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++column;
        return SourcePos{line_, column};
    }

    std::string_view text_;
    std::string error_;
    std::vector<std::string_view> stack_;
    std::optional<std::uint32_t> vendor_id_;
    std::string vendor_name_;
    bool have_vendor_name_ = false;
    bool english_vendor_name_ = false;
    std::optional<ScannedDevice> device_;
    std::vector<HiddenIdentity> hides_;  // of the Device being read (its Type may come after them)
    std::size_t device_depth_ = 0;
    std::size_t ordinal_ = 0;
    bool have_name_ = false;
    bool english_name_ = false;
    bool have_type_ = false;
    std::size_t counted_ = 0;
    std::size_t line_start_ = 0;
    std::uint32_t line_ = 1;
};

}  // namespace

IdentityScan scan_identities(std::string bytes) {
    const DecodedText decoded = decode_xml_bytes_owned(std::move(bytes));
    return Scanner(decoded.utf8).run();
}

}  // namespace esi
