#include "xml/namespace_prefixes.hpp"

#include <optional>

namespace esi {

namespace {

// The prefix of a qualified name ("xsi" of "xsi:type"); empty when it has none.
std::string_view prefix_of(std::string_view name) {
    const std::size_t colon = name.find(':');
    return colon == std::string_view::npos ? std::string_view() : name.substr(0, colon);
}

bool declared(xml_tree::Element element, std::string_view prefix) {
    // "xml" is bound by the XML namespaces recommendation itself, "xmlns" is the declaration syntax.
    if (prefix == "xml" || prefix == "xmlns") return true;
    const std::string declaration = "xmlns:" + std::string(prefix);
    for (xml_tree::Element n = element; n; n = n.parent())
        if (n.attribute(declaration)) return true;
    return false;
}

}  // namespace

UndeclaredPrefixCheck::UndeclaredPrefixCheck(const SourceText& source, xml_tree::TreeParser& parser, xml_tree::Element root,
                                             Diagnostics& diagnostics)
    : source_(source), parser_(parser), root_name_end_(root.offset() + 1 + root.name().size()), diagnostics_(diagnostics) {}

void UndeclaredPrefixCheck::start_tag(xml_tree::Element element) {
    // The name follows the '<' on its line.
    check(element, element.name(), SourcePos{element.pos().line, element.pos().column + 1});
    for (const xml_tree::Attribute& a : element.attributes())
        if (!prefix_of(a.name).empty()) check(element, a.name, parser_.position_of(a.name.data()));
}

void UndeclaredPrefixCheck::check(xml_tree::Element element, std::string_view name, SourcePos pos) {
    const std::string_view prefix = prefix_of(name);
    if (prefix.empty() || reported_.count(prefix) || declared(element, prefix)) return;
    reported_.emplace(prefix);
    std::string message = "the prefix '" + excerpt(prefix) + "' of '" + excerpt(name) + "' is not declared (no xmlns:" +
                          excerpt(prefix) + " on this or an enclosing element); namespace-aware XML readers reject the file";
    if (prefix == "xsi") message += "; declare xmlns:xsi=\"" + std::string(xml_schema_instance_namespace) + "\" on the root element";
    Diagnostic& d = diagnostics_.emplace(Severity::error, "xml-undeclared-prefix", std::move(message), source_.path(), pos);
    // Inserted right after the root element's name, where it cannot split anything.
    if (prefix == "xsi")
        d.fix = Fix{"declare xmlns:xsi on the root element",
                    {TextEdit{root_name_end_, 0, " xmlns:xsi=\"" + std::string(xml_schema_instance_namespace) + "\""}}};
}

}  // namespace esi
