// Completion: what may be typed at the cursor. In an ESI file the text before the cursor tells
// where it stands (the enclosing elements, a tag name being typed, an element's value); the
// editor's text is usually not well-formed while typing, so this is a scan of the text, not of
// the parse tree. The values offered come from the index of the enclosing device.

#include <set>
#include <string>

#include "esi/data_types.hpp"
#include "navigate/format.hpp"
#include "navigate/index.hpp"
#include "navigate/schema_children.hpp"

namespace esi::navigate {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.' || c == ':' || static_cast<unsigned char>(c) >= 0x80;
}

struct XmlCursor {
    enum class Where { text, tag_name, elsewhere } where = Where::elsewhere;
    std::vector<std::string_view> open;  // enclosing elements, innermost last
    std::size_t token_begin = 0;
    std::size_t token_end = 0;
};

// Scans tags from `from` (a point between elements) up to the cursor.
XmlCursor scan_to(std::string_view text, std::size_t from, std::size_t cursor) {
    XmlCursor out;
    std::size_t i = from;
    auto skip_past = [&](std::string_view terminator, std::size_t start) -> bool {
        const std::size_t end = text.find(terminator, start);
        if (end == std::string_view::npos || end + terminator.size() > cursor) return false;
        i = end + terminator.size();
        return true;
    };
    while (true) {
        const std::size_t lt = text.find('<', i);
        if (lt == std::string_view::npos || lt >= cursor) break;
        const std::string_view rest = text.substr(lt);
        if (rest.starts_with("<!--")) {
            if (!skip_past("-->", lt + 4)) return out;
        } else if (rest.starts_with("<![CDATA[")) {
            if (!skip_past("]]>", lt + 9)) return out;
        } else if (rest.starts_with("<?")) {
            if (!skip_past("?>", lt + 2)) return out;
        } else if (rest.starts_with("<!")) {
            if (!skip_past(">", lt + 2)) return out;
        } else if (rest.starts_with("</")) {
            std::size_t end = lt + 2;
            while (end < text.size() && is_name_char(text[end])) ++end;
            const std::string_view name = text.substr(lt + 2, end - lt - 2);
            if (!skip_past(">", end)) return out;
            // Close up to the matching element; a stray end tag closes nothing.
            for (std::size_t k = out.open.size(); k-- > 0;)
                if (out.open[k] == name) {
                    out.open.resize(k);
                    break;
                }
        } else {
            std::size_t end = lt + 1;
            while (end < text.size() && is_name_char(text[end])) ++end;
            if (cursor <= end) {
                out.where = XmlCursor::Where::tag_name;
                out.token_begin = lt + 1;
                out.token_end = end;
                return out;
            }
            const std::string_view name = text.substr(lt + 1, end - lt - 1);
            char quote = 0;
            std::size_t gt = std::string_view::npos;
            for (std::size_t k = end; k < text.size(); ++k) {
                const char c = text[k];
                if (quote) {
                    if (c == quote) quote = 0;
                } else if (c == '"' || c == '\'') {
                    quote = c;
                } else if (c == '>') {
                    gt = k;
                    break;
                } else if (c == '<') {
                    break;  // a tag never finished: the next one starts
                }
            }
            if (gt == std::string_view::npos || gt >= cursor) return out;  // in the start tag's attributes
            if (text[gt - 1] != '/' && !name.empty()) out.open.push_back(name);
            i = gt + 1;
        }
    }
    out.where = XmlCursor::Where::text;
    std::size_t begin = cursor;
    while (begin > i && !is_blank(text[begin - 1]) && text[begin - 1] != '>') --begin;
    std::size_t end = cursor;
    while (end < text.size() && !is_blank(text[end]) && text[end] != '<') ++end;
    out.token_begin = begin;
    out.token_end = end;
    return out;
}

std::string_view at_depth(const std::vector<std::string_view>& open, std::size_t from_top) {
    return open.size() > from_top ? open[open.size() - 1 - from_top] : std::string_view{};
}

void add_objects(const Index& index, const Scope& scope, const Range& replace, std::vector<CompletionItem>& out) {
    for (const ObjectDef& object : scope.objects) {
        std::string label = format_index(object.index, index.yaml);
        out.push_back(CompletionItem{label, CompletionKind::object, object.name, label, replace});
    }
}

void add_pdos(const Index& index, const Scope& scope, const Range& replace, std::vector<CompletionItem>& out) {
    for (const PdoDef& pdo : scope.pdos) {
        std::string label = format_index(pdo.index, index.yaml);
        out.push_back(CompletionItem{label, CompletionKind::value,
                                     std::string(pdo.tx ? "TxPdo " : "RxPdo ") + pdo.name, label, replace});
    }
}

void add_data_types(const Scope* scope, const Range& replace, std::vector<CompletionItem>& out) {
    std::set<std::string_view> seen;
    if (scope)
        for (const DataTypeDef& type : scope->data_types)
            if (!type.name.empty() && seen.insert(type.name).second)
                out.push_back(CompletionItem{type.name, CompletionKind::data_type, bits_text(type.bit_size), type.name, replace});
    add_basic_types(replace, seen, out);
}

void add_elements(std::string_view parent, std::string_view grandparent, bool in_tag, const Range& replace,
                  std::vector<CompletionItem>& out) {
    for (const std::string_view name : schema_children(parent, grandparent)) {
        std::string insert = in_tag ? std::string(name) : "<" + std::string(name) + "></" + std::string(name) + ">";
        out.push_back(CompletionItem{std::string(name), CompletionKind::element, std::string(parent), std::move(insert),
                                     replace});
    }
}

std::vector<CompletionItem> complete_xml(const Index& index, std::size_t offset) {
    const auto scope_number = index.scope_at(offset);
    const Scope* scope = scope_number ? &index.scopes[*scope_number] : nullptr;
    // Inside a device the scan starts at the device's tag: what encloses the device is known.
    const XmlCursor cursor = scan_to(index.text, scope ? scope->element.begin : 0, offset);
    const Range replace = index.lines.range_of(cursor.token_begin, cursor.token_end);
    std::vector<CompletionItem> out;
    if (cursor.where == XmlCursor::Where::tag_name) {
        if (scope && cursor.open.empty()) return out;  // the device's own tag
        const std::string_view parent = cursor.open.empty() ? std::string_view{} : at_depth(cursor.open, 0);
        if (parent.empty()) {
            out.push_back(CompletionItem{"EtherCATInfo", CompletionKind::element, "", "EtherCATInfo", replace});
            return out;
        }
        // The grandparent of a device's first level is Devices or Modules, outside the scan.
        add_elements(parent, at_depth(cursor.open, 1), true, replace, out);
        return out;
    }
    if (cursor.where != XmlCursor::Where::text || cursor.open.empty()) return out;
    const std::string_view element = at_depth(cursor.open, 0);
    const std::string_view parent = at_depth(cursor.open, 1);
    if (scope && element == "Index" && (parent == "Entry" || parent == "InitCmd")) {
        add_objects(index, *scope, replace, out);
    } else if (scope && ((element == "Pdo" && parent == "Sm") || (element == "Exclude"))) {
        add_pdos(index, *scope, replace, out);
    } else if ((element == "Type" && (parent == "Object" || parent == "SubItem")) || element == "BaseType" ||
               (element == "DataType" && parent == "Entry")) {
        add_data_types(scope, replace, out);
    } else if (cursor.token_begin == cursor.token_end) {
        add_elements(element, parent, false, replace, out);
    }
    return out;
}

}  // namespace

void add_basic_types(const Range& replace, std::set<std::string_view>& seen, std::vector<CompletionItem>& out) {
    for (const BasicType& basic : basic_types()) {
        if (!seen.insert(basic.esi_name).second) continue;
        std::string detail(basic.coe_name);
        if (basic.bit_size != 0) detail += ", " + bits_text(std::to_string(basic.bit_size));
        out.push_back(CompletionItem{std::string(basic.esi_name), CompletionKind::data_type, std::move(detail),
                                     std::string(basic.esi_name), replace});
    }
}

std::vector<CompletionItem> complete_yaml(const Index& index, std::size_t offset);  // completion_yaml.cpp

std::vector<CompletionItem> complete(const Index& index, Position position) {
    const auto offset = index.lines.offset_of(position);
    if (!offset) return {};
    if (index.yaml) return complete_yaml(index, *offset);
    return complete_xml(index, *offset);
}

}  // namespace esi::navigate
