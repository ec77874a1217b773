#pragma once
// Namespace prefixes used without a declaration (xml-undeclared-prefix). ESI files use one
// prefix as a rule, xsi: for xsi:noNamespaceSchemaLocation or xsi:type, and a file edited by hand
// sometimes keeps the attribute and loses the xmlns:xsi declaration on the root. libesi reads
// names as written, so nothing here changes the model; namespace-aware parsers (the .NET reader of
// configuration tools, libxml2 behind xmllint --schema) refuse or misread such a document.

#include <set>
#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"
#include "esi/source_text.hpp"
#include "xml/tree_parser.hpp"

namespace esi {

// The namespace the xsi: prefix stands for by convention; the safe fix declares it on the root.
inline constexpr std::string_view xml_schema_instance_namespace = "http://www.w3.org/2001/XMLSchema-instance";

// One xml-undeclared-prefix error per prefix that an element or attribute name uses while no
// element around it declares it, at its first use; run on the start tags with a prefixed name
// while the parser's pass is at them. The one for xsi: carries the fix declaring it on the root
// element.
class UndeclaredPrefixCheck final : public xml_tree::StartTagObserver {
public:
    UndeclaredPrefixCheck(const SourceText& source, xml_tree::TreeParser& parser, xml_tree::Element root, Diagnostics& diagnostics);
    void start_tag(xml_tree::Element element) override;

private:
    void check(xml_tree::Element element, std::string_view name, SourcePos pos);

    const SourceText& source_;
    xml_tree::TreeParser& parser_;
    std::size_t root_name_end_;  // offset right after the root element's name
    Diagnostics& diagnostics_;
    std::set<std::string, std::less<>> reported_;
};

}  // namespace esi
