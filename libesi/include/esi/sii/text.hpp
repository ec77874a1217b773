#pragma once
// SII strings are bytes; ESI text is UTF-8 in the model. Beckhoff's images hold ISO-8859-1
// (the EL2262 image stores "µs" as 0xB5 'µ'), so that is what the builder writes.

#include <string>
#include <string_view>

namespace esi::sii {

// The text as SII stores it: ISO-8859-1 when every character fits, else the UTF-8 bytes
// unchanged (`latin1` tells which).
[[nodiscard]] std::string to_sii_text(std::string_view utf8, bool* latin1 = nullptr);
// SII string bytes as UTF-8 for display: valid UTF-8 stays, anything else is read as ISO-8859-1.
[[nodiscard]] std::string sii_text_to_utf8(std::string_view bytes);

}  // namespace esi::sii
