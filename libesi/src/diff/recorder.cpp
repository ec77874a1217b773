#include "diff/recorder.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <vector>

#include <fmt/format.h>

namespace esi::diff_detail {

void Recorder::add(ChangeKind kind, std::string path, std::optional<std::string> old_value, std::optional<std::string> new_value,
                   SourcePos old_pos, SourcePos new_pos, std::string message) {
    Change c;
    c.device = device_;
    c.path = std::move(path);
    c.kind = kind;
    c.change_class = classify(kind, context_);
    c.old_value = std::move(old_value);
    c.new_value = std::move(new_value);
    c.old_pos = old_pos;
    c.new_pos = new_pos;
    c.message = std::move(message);
    if (context_ == RevisionContext::added_revision && info(kind).change_class == ChangeClass::breaking && device_ &&
        device_->compared_revision)
        c.message += fmt::format(" (new revision; revision {} is still described, so configurations made for it are unaffected)",
                                 hex(*device_->compared_revision, 8));
    out_.push_back(std::move(c));
}

void Recorder::record_value(ChangeKind kind, const Path& path, std::string_view what, const std::optional<std::string>& old_value,
                            const std::optional<std::string>& new_value, SourcePos old_pos, SourcePos new_pos) {
    std::string message;
    if (old_value && new_value)
        message = fmt::format("{} changed from {} to {}", what, *old_value, *new_value);
    else if (new_value)
        message = fmt::format("{} {} added", what, *new_value);
    else
        message = fmt::format("{} {} removed", what, *old_value);
    add(kind, path.str(), old_value, new_value, old_pos, new_pos, std::move(message));
}

bool Recorder::breaking_since(std::size_t mark) const {
    for (std::size_t i = mark; i < out_.size(); ++i)
        if (out_[i].change_class == ChangeClass::breaking) return true;
    return false;
}

std::string Path::str() const {
    std::string out;
    out.reserve(prefix_.size() + separator_.size() + leaf_.size());
    out.append(prefix_).append(separator_).append(leaf_);
    return out;
}

Path child(std::string_view parent, std::string_view element) {
    if (parent.empty()) return Path(element, {}, {});
    return Path(parent, "/", element);
}

Path attr(std::string_view element, std::string_view attribute) { return Path(element, "@", attribute); }

std::string indexed(std::string_view element, std::string_view key) {
    std::string out;
    out.reserve(element.size() + key.size() + 2);
    out.append(element).append("[").append(key).append("]");
    return out;
}

std::string hex(std::uint64_t value, int digits) { return format_hex(value, digits); }

std::optional<std::string> hex(const std::optional<std::uint32_t>& value, int digits) {
    if (!value) return std::nullopt;
    return format_hex(*value, digits);
}

std::string dec(std::uint64_t value) { return std::to_string(value); }

std::optional<std::string> dec(const std::optional<std::uint32_t>& value) {
    if (!value) return std::nullopt;
    return std::to_string(*value);
}

std::optional<std::string> dec(const std::optional<std::int32_t>& value) {
    if (!value) return std::nullopt;
    return std::to_string(*value);
}

std::optional<std::string> dec(const std::optional<std::int64_t>& value) {
    if (!value) return std::nullopt;
    return std::to_string(*value);
}

std::string flag(const std::optional<bool>& value) { return value.value_or(false) ? "true" : "false"; }

std::optional<std::string> text(const std::optional<std::string>& value) {
    if (!value) return std::nullopt;
    return std::string(trim(*value));
}

std::string entry_key(std::uint32_t index, std::uint32_t subindex) {
    return fmt::format("{}:{:02X}", format_hex(index, 4), subindex);
}

std::string quote(std::string_view text) { return fmt::format("'{}'", text); }

std::string normalized_hex(const HexData& data) {
    std::string out = data.text;
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

namespace {

std::string lcid_key(const LocalizedText& t) { return t.lcid ? std::to_string(*t.lcid) : std::string(); }

// Unmodelled text can be long (embedded data, descriptions): messages quote the start of it.
std::string shortened(std::string_view text) {
    constexpr std::size_t limit = 80;
    if (text.size() <= limit) return std::string(text);
    std::size_t cut = limit;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // keep UTF-8 sequences whole
    return std::string(text.substr(0, cut)) + "…";
}

// One line of an element for messages: <Name a="b">text…</Name>, shortened.
std::string describe(const XmlElement& e) {
    std::string out = "<" + e.name;
    for (const auto& a : e.attributes) out += fmt::format(" {}=\"{}\"", a.name, a.value);
    out += ">";
    const std::string_view t = trim(e.text);
    if (!t.empty())
        out += std::string(t.substr(0, 60)) + (t.size() > 60 ? "…" : "");
    else if (!e.children.empty())
        out += "…";
    return out;
}

// Attribute order carries no meaning in XML; compare with the attributes sorted by name.
XmlElement sorted_attributes(const XmlElement& e) {
    XmlElement out = e;
    std::stable_sort(out.attributes.begin(), out.attributes.end(),
                     [](const XmlAttribute& x, const XmlAttribute& y) { return x.name < y.name; });
    for (auto& c : out.children) c = sorted_attributes(c);
    return out;
}

bool same_element(const XmlElement& a, const XmlElement& b) {
    if (same_content(a, b)) return true;
    return same_content(sorted_attributes(a), sorted_attributes(b));
}

// The first place where two elements differ, as a path below them and the two spellings.
struct Difference {
    std::string path;
    std::optional<std::string> old_value;
    std::optional<std::string> new_value;
};

// The first attribute whose values differ, by name; a name may repeat in a model built in
// memory (well-formed XML cannot hold one), so the values of a name are compared as a list.
std::optional<Difference> first_attribute_difference(const XmlElement& a, const XmlElement& b, const std::string& path) {
    std::map<std::string_view, std::vector<std::string_view>> aa;
    std::map<std::string_view, std::vector<std::string_view>> ba;
    for (const auto& x : a.attributes) aa[x.name].push_back(x.value);
    for (const auto& x : b.attributes) ba[x.name].push_back(x.value);
    auto value = [](const std::vector<std::string_view>& values, std::size_t i) {
        return i < values.size() ? std::optional<std::string>(values[i]) : std::nullopt;
    };
    std::set<std::string_view> names;
    for (const auto& [name, values] : aa) names.insert(name);
    for (const auto& [name, values] : ba) names.insert(name);
    static const std::vector<std::string_view> none;
    for (const std::string_view name : names) {
        const auto ia = aa.find(name);
        const auto ib = ba.find(name);
        const auto& va = ia == aa.end() ? none : ia->second;
        const auto& vb = ib == ba.end() ? none : ib->second;
        for (std::size_t i = 0; i < std::max(va.size(), vb.size()); ++i)
            if (value(va, i) != value(vb, i)) return Difference{attr(path, name), value(va, i), value(vb, i)};
    }
    return std::nullopt;
}

// Only called for elements that differ (same_element is false), so a difference exists; the
// whole element is named if none of the parts below is found to differ.
Difference first_difference(const XmlElement& a, const XmlElement& b, std::string path) {
    if (auto d = first_attribute_difference(a, b, path)) return std::move(*d);
    if (trim(a.text) != trim(b.text)) return {path, std::string(trim(a.text)), std::string(trim(b.text))};
    const std::size_t n = std::min(a.children.size(), b.children.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (same_element(a.children[i], b.children[i])) continue;
        if (a.children[i].name != b.children[i].name)
            return {child(path, a.children[i].name), describe(a.children[i]), describe(b.children[i])};
        return first_difference(a.children[i], b.children[i], child(path, a.children[i].name));
    }
    if (a.children.size() > n) return {child(path, a.children[n].name), describe(a.children[n]), std::nullopt};
    if (b.children.size() > n) return {child(path, b.children[n].name), std::nullopt, describe(b.children[n])};
    return {path, describe(a), describe(b)};
}

// Texts shown to users compare with whitespace runs collapsed: a name wrapped over two lines in
// one file and written on one line in the other is the same name.
bool same_text(std::string_view a, std::string_view b) {
    if (a == b) return true;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    std::size_t i = 0;
    std::size_t j = 0;
    while (true) {  // word by word
        while (i < a.size() && space(a[i])) ++i;
        while (j < b.size() && space(b[j])) ++j;
        if (i == a.size() || j == b.size()) return i == a.size() && j == b.size();
        while (i < a.size() && j < b.size() && !space(a[i]) && !space(b[j])) {
            if (a[i] != b[j]) return false;
            ++i;
            ++j;
        }
        if ((i < a.size() && !space(a[i])) || (j < b.size() && !space(b[j]))) return false;
    }
}

}  // namespace

void compare_texts(Recorder& r, ChangeKind kind, const std::string& path, std::string_view element, const Names& old_names,
                   const Names& new_names, SourcePos old_parent, SourcePos new_parent) {
    // Usually nothing changed: the same texts in the same order.
    if (old_names.size() == new_names.size() &&
        std::equal(old_names.begin(), old_names.end(), new_names.begin(),
                   [](const LocalizedText& x, const LocalizedText& y) { return x.lcid == y.lcid && same_text(x.text, y.text); }))
        return;
    // Per LcId; several texts with the same LcId (or none) pair up in order.
    std::map<std::string, std::vector<const LocalizedText*>> a;
    std::map<std::string, std::vector<const LocalizedText*>> b;
    for (const auto& t : old_names) a[lcid_key(t)].push_back(&t);
    for (const auto& t : new_names) b[lcid_key(t)].push_back(&t);
    std::vector<std::string> keys;
    for (const auto& [k, v] : a) keys.push_back(k);
    for (const auto& [k, v] : b)
        if (!a.count(k)) keys.push_back(k);
    std::sort(keys.begin(), keys.end());
    for (const auto& key : keys) {
        const auto& la = a[key];
        const auto& lb = b[key];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const LocalizedText* x = i < la.size() ? la[i] : nullptr;
            const LocalizedText* y = i < lb.size() ? lb[i] : nullptr;
            std::string label = key.empty() ? std::string(element) : indexed(element, key);
            if (i > 0) label += fmt::format("#{}", i + 1);
            const std::string p = child(path, label);
            if (x && y && same_text(x->text, y->text)) continue;
            const std::string what = key.empty() ? std::string(element) : fmt::format("{} (LcId {})", element, key);
            std::string message;
            if (x && y)
                message = fmt::format("{} changed from {} to {}", what, quote(x->text), quote(y->text));
            else if (y)
                message = fmt::format("{} {} added", what, quote(y->text));
            else
                message = fmt::format("{} {} removed", what, quote(x->text));
            r.add(kind, p, x ? std::optional<std::string>(x->text) : std::nullopt,
                  y ? std::optional<std::string>(y->text) : std::nullopt, x ? x->pos : old_parent, y ? y->pos : new_parent,
                  std::move(message));
        }
    }
}

void compare_extras(Recorder& r, const std::string& path, const Extras& old_extras, const Extras& new_extras,
                    SourcePos old_parent, SourcePos new_parent) {
    // Usually nothing changed: the same attributes and elements in the same order.
    if (old_extras.attributes == new_extras.attributes && old_extras.elements.size() == new_extras.elements.size() &&
        std::equal(old_extras.elements.begin(), old_extras.elements.end(), new_extras.elements.begin(),
                   [](const XmlElement& x, const XmlElement& y) { return same_content(x, y); }))
        return;
    std::map<std::string, std::string> aa;
    std::map<std::string, std::string> ba;
    for (const auto& x : old_extras.attributes) aa[x.name] = x.value;
    for (const auto& x : new_extras.attributes) ba[x.name] = x.value;
    std::vector<std::string> names;
    for (const auto& [k, v] : aa) names.push_back(k);
    for (const auto& [k, v] : ba)
        if (!aa.count(k)) names.push_back(k);
    std::sort(names.begin(), names.end());
    for (const auto& name : names) {
        const auto ia = aa.find(name);
        const auto ib = ba.find(name);
        r.value(
            ChangeKind::extras_changed, attr(path.empty() ? "." : path, name), [&] { return fmt::format("attribute {}", name); },
            ia == aa.end() ? std::nullopt : std::optional<std::string>(ia->second),
            ib == ba.end() ? std::nullopt : std::optional<std::string>(ib->second), old_parent, new_parent);
    }

    // Elements by name, k-th occurrence with k-th occurrence.
    std::map<std::string, std::vector<const XmlElement*>> ea;
    std::map<std::string, std::vector<const XmlElement*>> eb;
    std::vector<std::string> order;
    for (const auto& e : old_extras.elements) {
        if (!ea.count(e.name) && !eb.count(e.name)) order.push_back(e.name);
        ea[e.name].push_back(&e);
    }
    for (const auto& e : new_extras.elements) {
        if (!ea.count(e.name) && !eb.count(e.name)) order.push_back(e.name);
        eb[e.name].push_back(&e);
    }
    for (const auto& name : order) {
        const auto& la = ea[name];
        const auto& lb = eb[name];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const XmlElement* x = i < la.size() ? la[i] : nullptr;
            const XmlElement* y = i < lb.size() ? lb[i] : nullptr;
            const std::string label = n > 1 ? fmt::format("{}[{}]", name, i + 1) : name;
            const std::string p = child(path, label);
            if (x && y) {
                if (same_element(*x, *y)) continue;
                Difference d = first_difference(*x, *y, p);
                std::string message = fmt::format("unmodelled element {} changed", p);
                if (d.old_value && d.new_value)
                    message +=
                        fmt::format(": {} from {} to {}", d.path, quote(shortened(*d.old_value)), quote(shortened(*d.new_value)));
                else if (d.new_value)
                    message += fmt::format(": {} added", d.path);
                else
                    message += fmt::format(": {} removed", d.path);
                r.add(ChangeKind::extras_changed, d.path, d.old_value, d.new_value, x->pos, y->pos, std::move(message));
            } else if (y) {
                r.add(ChangeKind::extras_changed, p, std::nullopt, describe(*y), old_parent, y->pos,
                      fmt::format("unmodelled element {} added", p));
            } else {
                r.add(ChangeKind::extras_changed, p, describe(*x), std::nullopt, x->pos, new_parent,
                      fmt::format("unmodelled element {} removed", p));
            }
        }
    }
}

void compare_images(Recorder& r, const std::string& path, const Images& a, const Images& b, SourcePos old_parent,
                    SourcePos new_parent) {
    r.value(ChangeKind::image_changed, child(path, "Image16x14"), "Image16x14", a.image16x14, b.image16x14, old_parent,
            new_parent);
    r.value(ChangeKind::image_changed, child(path, "ImageFile16x14"), "ImageFile16x14", a.image_file16x14, b.image_file16x14,
            old_parent, new_parent);
    const auto da = a.image_data16x14 ? std::optional<std::string>(normalized_hex(*a.image_data16x14)) : std::nullopt;
    const auto db = b.image_data16x14 ? std::optional<std::string>(normalized_hex(*b.image_data16x14)) : std::nullopt;
    if (da != db) {
        const char* what = !da ? "added" : !db ? "removed" : "changed";
        r.add(ChangeKind::image_changed, child(path, "ImageData16x14"),
              da ? std::optional<std::string>(fmt::format("{} bytes", da->size() / 2)) : std::nullopt,
              db ? std::optional<std::string>(fmt::format("{} bytes", db->size() / 2)) : std::nullopt,
              a.image_data16x14 ? a.image_data16x14->pos : old_parent, b.image_data16x14 ? b.image_data16x14->pos : new_parent,
              fmt::format("ImageData16x14 {}", what));
    }
}

}  // namespace esi::diff_detail
