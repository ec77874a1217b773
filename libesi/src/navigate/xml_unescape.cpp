// Entity and character references in the values an index shows.

#include "navigate/xml_unescape.hpp"

#include <cstdlib>
#include <utility>

#include "esi/encoding.hpp"

namespace esi::navigate {

std::string unescape_xml_text(std::string_view raw) {
    if (raw.find('&') == std::string_view::npos) return std::string(raw);
    static constexpr std::pair<std::string_view, char> named[] = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string out;
    for (std::size_t i = 0; i < raw.size();) {
        bool replaced = false;
        if (raw[i] == '&') {
            for (const auto& [entity, c] : named)
                if (raw.substr(i, entity.size()) == entity) {
                    out += c;
                    i += entity.size();
                    replaced = true;
                    break;
                }
            const std::size_t semicolon = raw.find(';', i);
            if (!replaced && raw.substr(i, 2) == "&#" && semicolon != std::string_view::npos && semicolon - i <= 10) {
                const bool hex = raw.substr(i, 3) == "&#x";
                const std::string digits(raw.substr(i + (hex ? 3 : 2), semicolon - i - (hex ? 3 : 2)));
                char* end = nullptr;
                const unsigned long code = std::strtoul(digits.c_str(), &end, hex ? 16 : 10);
                if (!digits.empty() && end && *end == '\0' && code > 0 && code <= 0x10FFFF) {
                    append_utf8(out, static_cast<char32_t>(code));
                    i = semicolon + 1;
                    replaced = true;
                }
            }
        }
        if (!replaced) out += raw[i++];
    }
    return out;
}

}  // namespace esi::navigate
