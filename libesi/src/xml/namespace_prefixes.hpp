#pragma once
// Namespace prefixes used without a declaration (xml-undeclared-prefix). ESI files use one
// prefix as a rule, xsi: for xsi:noNamespaceSchemaLocation or xsi:type, and a file edited by hand
// sometimes keeps the attribute and loses the xmlns:xsi declaration on the root. libesi reads
// names as written, so nothing here changes the model; namespace-aware parsers (the .NET reader of
// configuration tools, libxml2 behind xmllint --schema) refuse or misread such a document.

#include <pugixml.hpp>

#include "esi/diagnostic.hpp"
#include "esi/source_text.hpp"

namespace esi {

// The namespace the xsi: prefix stands for by convention; the safe fix declares it on the root.
inline constexpr std::string_view xml_schema_instance_namespace = "http://www.w3.org/2001/XMLSchema-instance";

// One xml-undeclared-prefix error per prefix that an element or attribute name uses while no
// element around it declares it, at its first use. The one for xsi: carries the fix declaring it
// on the root element. `parse_buffer` is the in-place copy of `source` that `parsed` was read from.
void report_undeclared_prefixes(const SourceText& source, const pugi::xml_document& parsed, const char* parse_buffer,
                                Diagnostics& diagnostics);

}  // namespace esi
