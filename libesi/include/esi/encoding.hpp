#pragma once
// Turns the bytes of an XML file into UTF-8 at the boundary, once, so that every later stage
// (parser positions, rules, every output format) sees valid UTF-8. Vendors ship UTF-8 with
// and without BOM, UTF-16 (both byte orders) and the declared 8-bit encodings ISO-8859-1 and
// Windows-1252 (often spelled ISO8859-1).

#include <optional>
#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"

namespace esi {

enum class SourceEncoding { utf8, utf8_bom, utf16le, utf16be, latin1, windows1252 };

[[nodiscard]] std::string_view to_string(SourceEncoding encoding);

struct DecodedText {
    std::string utf8;
    SourceEncoding encoding = SourceEncoding::utf8;
    // Byte offset in `utf8` of the replacement for the first invalid sequence (npos when the
    // input was clean). Invalid bytes are replaced with U+FFFD so that reading can go on.
    std::size_t first_invalid_offset = std::string::npos;
    std::string declared;  // encoding named in the XML declaration, as written
};

// Detects the encoding from the BOM or the XML declaration and converts to UTF-8.
// Never fails: undecodable input is replaced and reported through first_invalid_offset.
[[nodiscard]] DecodedText decode_xml_bytes(std::string_view bytes);
// Same, reusing the buffer when the input already is valid UTF-8 (the common case).
[[nodiscard]] DecodedText decode_xml_bytes_owned(std::string bytes);

// When the bytes are their own UTF-8 text (valid UTF-8 with or without a byte-order mark, and
// no 8-bit encoding declared): where the text starts (after the mark), what they were, the
// declared encoding. Nothing when they have to be decoded.
struct Utf8InPlace {
    std::size_t offset = 0;
    SourceEncoding encoding = SourceEncoding::utf8;
    std::string declared;
};
[[nodiscard]] std::optional<Utf8InPlace> utf8_in_place(std::string_view bytes);

// True when text is valid UTF-8 (no overlongs, no surrogates, nothing above U+10FFFF).
[[nodiscard]] bool is_valid_utf8(std::string_view text, std::size_t* first_bad = nullptr);

// Appends the code point `cp` (at most U+10FFFF) to `out` as UTF-8.
void append_utf8(std::string& out, char32_t cp);

}  // namespace esi
