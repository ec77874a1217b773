#pragma once
// XInclude (W3C XML Inclusions) is not part of ESI: ETG.2000 defines no inclusion mechanism, and
// masters and configuration tools read an xi:include element as an unknown element, not as the
// content it names. libesi does not resolve includes either (that would read or fetch other
// files), and copying the element into a generated ESI file or YAML source would carry a
// reference whose relative href no longer points anywhere. So an XInclude element is an error
// (xml-xinclude, or yaml-xml in a YAML source's xml: snippet): the file has to be expanded first
// (for example with xmllint --xinclude).

#include <string>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "esi/diagnostic.hpp"

namespace esi {

// Elements in the XInclude namespace (the 2001 and 2003 URIs) at or below `top`, in document
// order. A text that does not name the namespace is not walked.
[[nodiscard]] std::vector<pugi::xml_node> find_xinclude_elements(std::string_view text, const pugi::xml_node top);

// What to say about one of them: an element named `name` with this href, if it has one.
[[nodiscard]] std::string describe_xinclude(std::string_view name, const std::string_view* href);
[[nodiscard]] std::string describe_xinclude(const pugi::xml_node element);

// Whether a text may hold an XInclude element: one needs its namespace declared, so a text
// without the word has none.
[[nodiscard]] bool may_hold_xinclude(std::string_view text);

}  // namespace esi
