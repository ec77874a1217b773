#include "esi/encoding.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cctype>
#include <cstring>

namespace esi {

std::string_view to_string(SourceEncoding encoding) {
    switch (encoding) {
        case SourceEncoding::utf8: return "UTF-8";
        case SourceEncoding::utf8_bom: return "UTF-8 (BOM)";
        case SourceEncoding::utf16le: return "UTF-16LE";
        case SourceEncoding::utf16be: return "UTF-16BE";
        case SourceEncoding::latin1: return "ISO-8859-1";
        case SourceEncoding::windows1252: return "Windows-1252";
    }
    return "UTF-8";
}

void append_utf8(std::string& out, char32_t cp) {
    if (cp < 0x80) {
        out.push_back(static_cast<char>(cp));
    } else if (cp < 0x800) {
        out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else if (cp < 0x10000) {
        out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else {
        out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    }
}

namespace {

constexpr std::string_view replacement = "\xEF\xBF\xBD";

// Windows-1252 bytes 0x80..0x9F; 0 marks the five undefined positions.
constexpr char16_t cp1252_high[32] = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

// Length of the valid UTF-8 sequence at p (0 when invalid).
std::size_t utf8_sequence_length(const unsigned char* p, std::size_t remaining) {
    const unsigned char c = p[0];
    if (c < 0x80) return 1;
    std::size_t length = 0;
    char32_t cp = 0;
    if ((c & 0xE0) == 0xC0) { length = 2; cp = c & 0x1F; }
    else if ((c & 0xF0) == 0xE0) { length = 3; cp = c & 0x0F; }
    else if ((c & 0xF8) == 0xF0) { length = 4; cp = c & 0x07; }
    else return 0;
    if (remaining < length) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((p[i] & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (p[i] & 0x3F);
    }
    if ((length == 2 && cp < 0x80) || (length == 3 && cp < 0x800) || (length == 4 && cp < 0x10000)) return 0;
    if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return length;
}

// The encoding pseudo-attribute of an XML declaration at the start of ASCII-compatible text.
std::string declared_encoding(std::string_view text) {
    if (text.substr(0, 5) != "<?xml") return {};
    const auto end = text.find("?>");
    const std::string_view decl = text.substr(0, end == std::string_view::npos ? std::min<std::size_t>(text.size(), 200) : end);
    const auto key = decl.find("encoding");
    if (key == std::string_view::npos) return {};
    auto pos = decl.find_first_of("\"'", key);
    if (pos == std::string_view::npos) return {};
    const char quote = decl[pos];
    const auto close = decl.find(quote, pos + 1);
    if (close == std::string_view::npos) return {};
    return std::string(decl.substr(pos + 1, close - pos - 1));
}

std::string upper(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return out;
}

DecodedText decode_utf16(std::string_view bytes, bool little_endian) {
    DecodedText out;
    out.encoding = little_endian ? SourceEncoding::utf16le : SourceEncoding::utf16be;
    out.utf8.reserve(bytes.size());
    auto unit_at = [&](std::size_t i) -> char16_t {
        const auto a = static_cast<unsigned char>(bytes[i]);
        const auto b = static_cast<unsigned char>(bytes[i + 1]);
        return static_cast<char16_t>(little_endian ? (a | (b << 8)) : ((a << 8) | b));
    };
    std::size_t i = 0;
    while (i + 1 < bytes.size()) {
        const char16_t unit = unit_at(i);
        if (unit >= 0xD800 && unit <= 0xDBFF) {
            if (i + 3 < bytes.size()) {
                const char16_t low = unit_at(i + 2);
                if (low >= 0xDC00 && low <= 0xDFFF) {
                    append_utf8(out.utf8, 0x10000 + ((static_cast<char32_t>(unit) - 0xD800) << 10) + (low - 0xDC00));
                    i += 4;
                    continue;
                }
            }
            if (out.first_invalid_offset == std::string::npos) out.first_invalid_offset = out.utf8.size();
            out.utf8 += replacement;
            i += 2;
        } else if (unit >= 0xDC00 && unit <= 0xDFFF) {
            if (out.first_invalid_offset == std::string::npos) out.first_invalid_offset = out.utf8.size();
            out.utf8 += replacement;
            i += 2;
        } else {
            append_utf8(out.utf8, unit);
            i += 2;
        }
    }
    if (i < bytes.size() && out.first_invalid_offset == std::string::npos) out.first_invalid_offset = out.utf8.size();
    return out;
}

// The end of the run of ASCII bytes (high bit clear) starting at `from`.
std::size_t ascii_run_end(std::string_view bytes, std::size_t from) {
    std::size_t i = from;
#if defined(__SSE2__)
    // 64 bytes a step (four blocks ORed, one test of their high bits), then the block that has
    // the byte: an 8-bit file is nearly all ASCII, and eight bytes a step still cost half an
    // instruction a byte.
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    while (i + 64 <= bytes.size()) {
        const auto* q = reinterpret_cast<const __m128i*>(p + i);
        const __m128i any = _mm_or_si128(_mm_or_si128(_mm_loadu_si128(q), _mm_loadu_si128(q + 1)),
                                         _mm_or_si128(_mm_loadu_si128(q + 2), _mm_loadu_si128(q + 3)));
        if (_mm_movemask_epi8(any) != 0) break;
        i += 64;
    }
    while (i + 16 <= bytes.size()) {
        const int high = _mm_movemask_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p + i)));
        if (high != 0) return i + static_cast<std::size_t>(__builtin_ctz(static_cast<unsigned>(high)));
        i += 16;
    }
#endif
    while (i + 8 <= bytes.size()) {
        std::uint64_t chunk = 0;
        std::memcpy(&chunk, bytes.data() + i, 8);
        if (chunk & 0x8080808080808080ull) break;
        i += 8;
    }
    while (i < bytes.size() && static_cast<unsigned char>(bytes[i]) < 0x80) ++i;
    return i;
}

DecodedText decode_8bit(std::string_view bytes, bool windows1252) {
    DecodedText out;
    out.encoding = windows1252 ? SourceEncoding::windows1252 : SourceEncoding::latin1;
    out.utf8.reserve(bytes.size() + bytes.size() / 16);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (c < 0x80) {
            // Copy the whole ASCII run at once; the run is found eight bytes at a time (vendor
            // files are almost all ASCII, and a byte loop cost four instructions a byte).
            std::size_t run = ascii_run_end(bytes, i + 1);
            out.utf8.append(bytes.substr(i, run - i));
            i = run - 1;
        } else if (windows1252 && c < 0xA0) {
            const char16_t mapped = cp1252_high[c - 0x80];
            if (mapped == 0) {
                if (out.first_invalid_offset == std::string::npos) out.first_invalid_offset = out.utf8.size();
                out.utf8 += replacement;
            } else {
                append_utf8(out.utf8, mapped);
            }
        } else {
            append_utf8(out.utf8, c);
        }
    }
    return out;
}

}  // namespace

bool is_valid_utf8(std::string_view text, std::size_t* first_bad) {
    const auto* p = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        // Fast path over ASCII (ascii_run_end): every UTF-8 file is validated whole before
        // parsing, and the loop overhead was half the cost.
        i = ascii_run_end(text, i);
        if (i >= n) break;
        const std::size_t length = utf8_sequence_length(p + i, n - i);
        if (length == 0) {
            if (first_bad) *first_bad = i;
            return false;
        }
        i += length;
    }
    return true;
}

std::optional<Utf8InPlace> utf8_in_place(std::string_view bytes) {
    // Plain UTF-8 (with or without BOM, no 8-bit declaration) is its own text.
    const bool utf16 = bytes.size() >= 2 && ((static_cast<unsigned char>(bytes[0]) == 0xFF && static_cast<unsigned char>(bytes[1]) == 0xFE) ||
                                             (static_cast<unsigned char>(bytes[0]) == 0xFE && static_cast<unsigned char>(bytes[1]) == 0xFF) ||
                                             bytes[0] == '\0' || bytes[1] == '\0');
    if (utf16) return std::nullopt;
    const bool bom = bytes.size() >= 3 && bytes.substr(0, 3) == "\xEF\xBB\xBF";
    const std::string_view body = bytes.substr(bom ? 3 : 0);
    std::string declared = declared_encoding(body);
    const std::string name = upper(declared);
    const bool eight_bit = !bom && (name == "ISO-8859-1" || name == "ISO8859-1" || name == "LATIN1" || name == "ISO_8859-1" ||
                                    name == "ISO-8859-15" || name == "WINDOWS-1252" || name == "CP1252");
    if (eight_bit || !is_valid_utf8(body)) return std::nullopt;
    return Utf8InPlace{bom ? std::size_t{3} : std::size_t{0}, bom ? SourceEncoding::utf8_bom : SourceEncoding::utf8, std::move(declared)};
}

DecodedText decode_xml_bytes_owned(std::string bytes) {
    if (std::optional<Utf8InPlace> in_place = utf8_in_place(bytes)) {
        DecodedText out;
        out.encoding = in_place->encoding;
        out.declared = std::move(in_place->declared);
        if (in_place->offset) bytes.erase(0, in_place->offset);
        out.utf8 = std::move(bytes);
        return out;
    }
    DecodedText out = decode_xml_bytes(std::string_view(bytes));
    std::string().swap(bytes);  // the raw bytes are no longer needed
    return out;
}

DecodedText decode_xml_bytes(std::string_view bytes) {
    // Byte-order marks first, then the UTF-16 shape of "<?" without a BOM.
    if (bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0xFF && static_cast<unsigned char>(bytes[1]) == 0xFE)
        return decode_utf16(bytes.substr(2), true);
    if (bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0xFE && static_cast<unsigned char>(bytes[1]) == 0xFF)
        return decode_utf16(bytes.substr(2), false);
    if (bytes.size() >= 4 && bytes[0] == '<' && bytes[1] == '\0' && bytes[2] == '?' && bytes[3] == '\0')
        return decode_utf16(bytes, true);
    if (bytes.size() >= 4 && bytes[0] == '\0' && bytes[1] == '<' && bytes[2] == '\0' && bytes[3] == '?')
        return decode_utf16(bytes, false);

    bool bom = false;
    if (bytes.size() >= 3 && bytes.substr(0, 3) == "\xEF\xBB\xBF") {
        bytes.remove_prefix(3);
        bom = true;
    }
    const std::string declared = declared_encoding(bytes);
    const std::string name = upper(declared);
    if (!bom && (name == "ISO-8859-1" || name == "ISO8859-1" || name == "LATIN1" || name == "ISO_8859-1" ||
                 name == "ISO-8859-15" || name == "WINDOWS-1252" || name == "CP1252")) {
        // Windows-1252 is a superset of ISO-8859-1 for printable characters; files declared
        // ISO-8859-1 often contain Windows-1252 quotes, so both decode through the 1252 table.
        DecodedText out = decode_8bit(bytes, true);
        if (name != "WINDOWS-1252" && name != "CP1252") out.encoding = SourceEncoding::latin1;
        out.declared = declared;
        return out;
    }
    DecodedText out;
    out.encoding = bom ? SourceEncoding::utf8_bom : SourceEncoding::utf8;
    out.declared = declared;
    std::size_t bad = 0;
    if (is_valid_utf8(bytes, &bad)) {
        out.utf8.assign(bytes);
        return out;
    }
    // Replace invalid sequences so that the rest of the file can still be read.
    out.first_invalid_offset = bad;
    out.utf8.reserve(bytes.size() + 16);
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t i = 0;
    while (i < bytes.size()) {
        const std::size_t length = utf8_sequence_length(p + i, bytes.size() - i);
        if (length == 0) {
            out.utf8 += replacement;
            ++i;
        } else {
            out.utf8.append(bytes.substr(i, length));
            i += length;
        }
    }
    return out;
}

}  // namespace esi
