#pragma once
// Text as it goes into a page: escaped for HTML and SVG, numbers in the notation of EtherCAT
// documentation (0x6000:01), and names shortened to fit a box. Private to the doc layer.

#include <cstdint>
#include <string>
#include <string_view>

namespace esi::doc {

// Appends `text` with & < > " escaped, so it is safe as element text and as a quoted attribute.
void append_escaped(std::string& out, std::string_view text);
[[nodiscard]] std::string escaped(std::string_view text);

// "0x1A00" with at least `digits` upper-case hex digits.
[[nodiscard]] std::string hex(std::uint64_t value, int digits);
// "0x6000:01": an object index and sub-index as EtherCAT documentation writes them.
[[nodiscard]] std::string index_text(std::uint32_t index, std::uint32_t subindex);

// The width of UTF-8 text in columns of a monospace font: one per code point, two for East Asian
// wide ones (CJK, Hangul, full-width forms), so shortening never splits a character.
[[nodiscard]] std::size_t display_columns(std::string_view text);
// `text` when it fits in `columns`, else its longest prefix that fits with "…" appended (whole
// code points only); "" when not even one character and the ellipsis fit.
[[nodiscard]] std::string shortened(std::string_view text, std::size_t columns);

// A name for a file or an HTML id: [A-Za-z0-9._-] kept, runs of anything else become one '-',
// no leading or trailing '-'; `fallback` when nothing is left.
[[nodiscard]] std::string slug(std::string_view text, std::string_view fallback);

}  // namespace esi::doc
