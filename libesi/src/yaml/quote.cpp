#include "esi/yaml/quote.hpp"

#include <cstdint>
#include <cstdio>

namespace esi::yaml {

namespace {

// The code point of the well-formed UTF-8 sequence at s[i] and its length; 0 for a byte that
// starts none (stray continuation, truncated, overlong, surrogate, beyond U+10FFFF).
std::size_t decode(std::string_view s, std::size_t i, std::uint32_t& cp) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const unsigned char c = byte(0);
    const std::size_t len = c < 0x80 ? 1 : c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (len == 0 || i + len > s.size()) return 0;
    cp = len == 1 ? c : len == 2 ? (c & 0x1Fu) : len == 3 ? (c & 0x0Fu) : (c & 0x07u);
    for (std::size_t k = 1; k < len; ++k) {
        if ((byte(k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(k) & 0x3Fu);
    }
    static constexpr std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < smallest[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return len;
}

bool needs_escape(std::uint32_t cp, bool ascii_only) {
    if (cp < 0x20 || cp == 0x7F) return true;
    if (cp < 0x80) return false;
    if (ascii_only) return true;
    return cp < 0xA0 || cp == 0x2028 || cp == 0x2029 || cp == 0xFEFF || cp == 0xFFFE || cp == 0xFFFF;
}

}  // namespace

QuotedText double_quoted(std::string_view text, bool ascii_only) {
    QuotedText out;
    std::string& q = out.text;
    q.reserve(text.size() + 2);
    q += '"';
    char buffer[16];
    for (std::size_t i = 0; i < text.size();) {
        std::uint32_t cp = 0;
        const std::size_t len = decode(text, i, cp);
        if (len == 0) {
            out.ok = false;
            std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[i])));
            q += buffer;
            ++i;
            continue;
        }
        if (cp == '"') q += "\\\"";
        else if (cp == '\\') q += "\\\\";
        else if (cp == '\n') q += "\\n";
        else if (cp == '\r') q += "\\r";
        else if (cp == '\t') q += "\\t";
        else if (cp == 0x85) q += "\\N";
        else if (cp == 0x2028) q += "\\L";
        else if (cp == 0x2029) q += "\\P";
        else if (needs_escape(cp, ascii_only)) {
            if (cp <= 0xFF) std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(cp));
            else if (cp <= 0xFFFF) std::snprintf(buffer, sizeof buffer, "\\u%04X", static_cast<unsigned>(cp));
            else std::snprintf(buffer, sizeof buffer, "\\U%08X", static_cast<unsigned>(cp));
            q += buffer;
        } else {
            q.append(text.substr(i, len));
        }
        i += len;
    }
    q += '"';
    return out;
}

}  // namespace esi::yaml
