#include "esi/xml/xinclude.hpp"

#include <optional>

#include "xml/xinclude_check.hpp"

namespace esi {

namespace {

bool is_xinclude_namespace(std::string_view uri) {
    return uri == "http://www.w3.org/2001/XInclude" || uri == "http://www.w3.org/2003/XInclude";
}

// Whether an element named `name` is in the XInclude namespace. `nearest(declaration)` gives the
// value of the attribute of that name ("xmlns" or "xmlns:prefix") on the element or its nearest
// ancestor that has one, or nothing.
template <class Nearest>
bool in_xinclude_namespace(std::string_view name, Nearest&& nearest) {
    const auto colon = name.find(':');
    const std::string_view prefix = colon == std::string_view::npos ? std::string_view() : name.substr(0, colon);
    const std::string_view local = colon == std::string_view::npos ? name : name.substr(colon + 1);
    if (local != "include" && local != "fallback") return false;  // the only two XInclude elements
    const std::string declaration = prefix.empty() ? std::string("xmlns") : "xmlns:" + std::string(prefix);
    const std::optional<std::string_view> uri = nearest(declaration);
    return uri && is_xinclude_namespace(*uri);
}

bool in_xinclude_namespace(const pugi::xml_node element) {
    return in_xinclude_namespace(element.name(), [&](const std::string& declaration) -> std::optional<std::string_view> {
        for (pugi::xml_node n = element; n && n.type() == pugi::node_element; n = n.parent())
            if (const pugi::xml_attribute a = n.attribute(declaration.c_str())) return std::string_view(a.value());
        return std::nullopt;
    });
}

}  // namespace

// The search starts at a byte rare in ESI files ('X'), so it costs little.
bool may_hold_xinclude(std::string_view text) { return text.find("XInclude") != std::string_view::npos; }

std::vector<pugi::xml_node> find_xinclude_elements(std::string_view text, const pugi::xml_node top) {
    std::vector<pugi::xml_node> found;
    if (!may_hold_xinclude(text)) return found;
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

std::string describe_xinclude(std::string_view name, const std::string_view* href) {
    std::string message = "<" + excerpt(name) + ">: XInclude is not part of ESI (ETG.2000 defines no inclusion)";
    if (href) message += "; the content of '" + excerpt(*href) + "'";
    else message += "; the included content";
    return message + " is not read, and the element would be copied as it stands into generated files: expand the include first "
                     "(xmllint --xinclude)";
}

std::string describe_xinclude(const pugi::xml_node element) {
    if (const pugi::xml_attribute href = element.attribute("href")) {
        const std::string_view value = href.value();
        return describe_xinclude(element.name(), &value);
    }
    return describe_xinclude(element.name(), nullptr);
}

// ---- the reader's check, on its element tree ------------------------------------------------

XIncludeCheck::XIncludeCheck(const SourceText& source, xml_tree::TreeParser& parser, xml_tree::Element root, Diagnostics& diagnostics)
    : source_(source), parser_(parser), diagnostics_(diagnostics) {
    parser_.observe_namespaces(this);
    for (const xml_tree::Attribute& a : root.attributes())
        if (xml_tree::is_namespace_declaration(a.name)) declared(a.value);
    if (watching_) start_tag(root);
}

void XIncludeCheck::declared(std::string_view uri) {
    if (watching_ || !is_xinclude_namespace(uri)) return;
    watching_ = true;
    parser_.observe(this, parser_.prefix_observer());
}

void XIncludeCheck::start_tag(xml_tree::Element element) {
    const bool xinclude = in_xinclude_namespace(element.name(), [&](const std::string& declaration) -> std::optional<std::string_view> {
        for (xml_tree::Element n = element; n; n = n.parent())
            if (const xml_tree::Attribute* a = n.attribute(declaration)) return a->value;
        return std::nullopt;
    });
    if (!xinclude) return;
    const xml_tree::Attribute* href = element.attribute("href");
    diagnostics_.emplace(Severity::error, "xml-xinclude", describe_xinclude(element.name(), href ? &href->value : nullptr),
                         source_.path(), element.pos());
}

}  // namespace esi
