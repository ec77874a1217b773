#pragma once
// The tokens of an index are the text as written; the names and values a hover or the outline
// shows are read as XML reads them: the predefined entities and character references replaced
// ("R&amp;D" is "R&D", "&#x3A9;" is "\u03A9"). Anything else (an unknown entity, a broken
// reference) stays as written.

#include <string>
#include <string_view>

namespace esi::navigate {

[[nodiscard]] std::string unescape_xml_text(std::string_view raw);

}  // namespace esi::navigate
