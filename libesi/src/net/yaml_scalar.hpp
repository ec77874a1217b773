#pragma once
// Text in the YAML files esi-net writes: always a double-quoted scalar, so no text a user or
// an ESI supplies can turn into a number, a boolean, a null, a comment or more structure.
// Control characters, DEL, C1 controls and bytes that are not valid UTF-8 are escaped.

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace esi::net {

inline std::string yaml_quoted(std::string_view text) {
    std::string out = "\"";
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        std::size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        std::uint32_t cp = c;
        if (len > 1) {
            if (i + len > text.size()) len = 0;
            else {
                cp = len == 2 ? (c & 0x1Fu) : len == 3 ? (c & 0x0Fu) : (c & 0x07u);
                for (std::size_t k = 1; k < len && len; ++k) {
                    const unsigned char d = static_cast<unsigned char>(text[i + k]);
                    if ((d & 0xC0) != 0x80) len = 0;
                    else cp = (cp << 6) | (d & 0x3Fu);
                }
            }
        }
        char buffer[12];
        if (len == 0) {  // not UTF-8: keep the byte visible
            std::snprintf(buffer, sizeof buffer, "\\x%02X", c);
            out += buffer;
            ++i;
            continue;
        }
        if (cp == '"') out += "\\\"";
        else if (cp == '\\') out += "\\\\";
        else if (cp == '\n') out += "\\n";
        else if (cp == '\t') out += "\\t";
        else if (cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp < 0xA0) || cp == 0x2028 || cp == 0x2029 || cp == 0xFEFF) {
            std::snprintf(buffer, sizeof buffer, cp <= 0xFF ? "\\x%02X" : "\\u%04X", static_cast<unsigned>(cp));
            out += buffer;
        } else {
            out.append(text.substr(i, len));
        }
        i += len;
    }
    return out + "\"";
}

// A YAML comment's text: the quoted form without its quotes, so a line break, a control
// character or an invalid byte cannot end the comment or the file's UTF-8.
inline std::string yaml_comment_text(std::string_view text) {
    const std::string q = yaml_quoted(text);
    return q.substr(1, q.size() - 2);
}

}  // namespace esi::net
