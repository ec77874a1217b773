#include "esi/xml/xinclude.hpp"

namespace esi {

namespace {

bool is_xinclude_namespace(std::string_view uri) {
    return uri == "http://www.w3.org/2001/XInclude" || uri == "http://www.w3.org/2003/XInclude";
}

bool in_xinclude_namespace(const pugi::xml_node element) {
    const std::string_view name = element.name();
    const auto colon = name.find(':');
    const std::string_view prefix = colon == std::string_view::npos ? std::string_view() : name.substr(0, colon);
    const std::string_view local = colon == std::string_view::npos ? name : name.substr(colon + 1);
    if (local != "include" && local != "fallback") return false;  // the only two XInclude elements
    const std::string declaration = prefix.empty() ? std::string("xmlns") : "xmlns:" + std::string(prefix);
    for (pugi::xml_node n = element; n && n.type() == pugi::node_element; n = n.parent())
        if (const pugi::xml_attribute a = n.attribute(declaration.c_str())) return is_xinclude_namespace(a.value());
    return false;
}

}  // namespace

std::vector<pugi::xml_node> find_xinclude_elements(std::string_view text, const pugi::xml_node top) {
    std::vector<pugi::xml_node> found;
    // An XInclude element needs its namespace declared, so a text without the word has none; the
    // search starts at a byte rare in ESI files ('X'), so it costs little.
    if (text.find("XInclude") == std::string_view::npos) return found;
    for (pugi::xml_node n = top; n;) {
        if (n.type() == pugi::node_element && in_xinclude_namespace(n)) found.push_back(n);
        // Depth first, in document order, without recursion.
        if (pugi::xml_node child = n.first_child()) {
            n = child;
            continue;
        }
        while (n && n != top && !n.next_sibling()) n = n.parent();
        if (!n || n == top) break;
        n = n.next_sibling();
    }
    return found;
}

std::string describe_xinclude(const pugi::xml_node element) {
    std::string message = "<" + excerpt(element.name()) + ">: XInclude is not part of ESI (ETG.2000 defines no inclusion)";
    if (const pugi::xml_attribute href = element.attribute("href")) message += "; the content of '" + excerpt(href.value()) + "'";
    else message += "; the included content";
    return message + " is not read, and the element would be copied as it stands into generated files: expand the include first "
                     "(xmllint --xinclude)";
}

void report_xinclude(const SourceText& source, const pugi::xml_document& parsed, const char* parse_buffer, Diagnostics& diagnostics) {
    for (const pugi::xml_node element : find_xinclude_elements(source.text(), parsed.document_element())) {
        const char* name = element.name();
        const bool ours = name > parse_buffer && name < parse_buffer + source.text().size();
        const SourcePos pos = ours ? source.position_of(static_cast<std::size_t>(name - parse_buffer) - 1) : SourcePos{};
        diagnostics.emplace(Severity::error, "xml-xinclude", describe_xinclude(element), source.path(), pos);
    }
}

}  // namespace esi
