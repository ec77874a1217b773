#include "esi/sii/text.hpp"

#include "esi/encoding.hpp"

namespace esi::sii {

std::string to_sii_text(std::string_view utf8, bool* latin1) {
    std::string out;
    out.reserve(utf8.size());
    // Only two-byte sequences C2/C3 xx reach U+0080-U+00FF; anything else above ASCII does not fit.
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const auto c = static_cast<unsigned char>(utf8[i]);
        if (c < 0x80) {
            out.push_back(static_cast<char>(c));
            continue;
        }
        if ((c == 0xC2 || c == 0xC3) && i + 1 < utf8.size() && (static_cast<unsigned char>(utf8[i + 1]) & 0xC0) == 0x80) {
            out.push_back(static_cast<char>(((c & 0x03) << 6) | (static_cast<unsigned char>(utf8[i + 1]) & 0x3F)));
            ++i;
            continue;
        }
        if (latin1) *latin1 = false;
        return std::string(utf8);
    }
    if (latin1) *latin1 = true;
    return out;
}

std::string sii_text_to_utf8(std::string_view bytes) {
    if (is_valid_utf8(bytes)) return std::string(bytes);
    std::string out;
    out.reserve(bytes.size() + bytes.size() / 2);
    for (const char ch : bytes) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x80) {
            out.push_back(static_cast<char>(c));
        } else {
            out.push_back(static_cast<char>(0xC0 | (c >> 6)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        }
    }
    return out;
}

}  // namespace esi::sii
