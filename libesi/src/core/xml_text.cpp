#include "esi/xml_text.hpp"

#include <cstddef>

namespace esi {

namespace {

constexpr std::string_view replacement_character = "\xEF\xBF\xBD";  // U+FFFD

bool continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// Length of the well-formed UTF-8 sequence at `s[i]` that is also an XML 1.0 Char, or 0.
std::size_t valid_sequence(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const std::size_t left = s.size() - i;
    const unsigned char c = byte(0);
    if (c >= 0xC2 && c <= 0xDF) return left >= 2 && continuation(byte(1)) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
        if (left < 3 || !continuation(byte(1)) || !continuation(byte(2))) return 0;
        if (c == 0xE0 && byte(1) < 0xA0) return 0;   // overlong
        if (c == 0xED && byte(1) >= 0xA0) return 0;  // UTF-16 surrogate
        if (c == 0xEF && byte(1) == 0xBF && (byte(2) == 0xBE || byte(2) == 0xBF)) return 0;  // U+FFFE, U+FFFF
        return 3;
    }
    if (c >= 0xF0 && c <= 0xF4) {
        if (left < 4 || !continuation(byte(1)) || !continuation(byte(2)) || !continuation(byte(3))) return 0;
        if (c == 0xF0 && byte(1) < 0x90) return 0;   // overlong
        if (c == 0xF4 && byte(1) >= 0x90) return 0;  // above U+10FFFF
        return 4;
    }
    return 0;
}

}  // namespace

void append_xml_escaped(std::string& out, std::string_view text, XmlTextKind kind) {
    const bool attribute = kind == XmlTextKind::attribute_value;
    std::size_t run_start = 0;
    std::size_t i = 0;
    const auto flush = [&] {
        if (i > run_start) out.append(text.data() + run_start, i - run_start);
    };
    while (i < text.size()) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x80 && c != '&' && c != '<' && c != '>' && !(attribute && c == '"')) {
            ++i;  // the common case: plain ASCII stays in the current run
            continue;
        }
        if (c >= 0x80) {
            if (const std::size_t n = valid_sequence(text, i); n != 0) {
                i += n;
                continue;
            }
        }
        flush();
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;  // also keeps "]]>" out of character data
            case '"': out += "&quot;"; break;
            // A parser normalises a literal CR to LF and, in attributes, TAB/LF to a space
            // (XML 1.0 §2.11, §3.3.3); character references keep them as they are.
            case '\r': out += "&#13;"; break;
            case '\t': attribute ? out += "&#9;" : out += '\t'; break;
            case '\n': attribute ? out += "&#10;" : out += '\n'; break;
            default: out += replacement_character; break;  // other C0 controls, invalid UTF-8
        }
        ++i;
        run_start = i;
    }
    flush();
}

std::string xml_chars_only(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80) {
            if (const std::size_t n = valid_sequence(text, i); n != 0) {
                out.append(text.substr(i, n));
                i += n;
                continue;
            }
            out += replacement_character;
        } else if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') {
            out += replacement_character;
        } else {
            out += static_cast<char>(c);
        }
        ++i;
    }
    return out;
}

std::string xml_escaped(std::string_view text, XmlTextKind kind) {
    std::string out;
    out.reserve(text.size());
    append_xml_escaped(out, text, kind);
    return out;
}

}  // namespace esi
