#include "check/source_edit.hpp"

#include "esi/source_text.hpp"

namespace esi::rules {

std::optional<Fix> replace_element_text(const EsiDocument& document, SourcePos element, std::string_view expected,
                                        std::string replacement, std::string description) {
    if (!document.source || !element.known() || element.line > document.source->line_count() || expected.empty())
        return std::nullopt;
    const SourceText& source = *document.source;
    const std::string& text = source.text();
    // The column counts code points: walk them to the byte offset of the '<'.
    std::size_t at = source.line_start(element.line);
    for (std::uint32_t column = 1; column < element.column && at < text.size(); ++column) {
        ++at;
        while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
    }
    if (at >= text.size() || text[at] != '<') return std::nullopt;
    const std::size_t tag_end = text.find('>', at);
    if (tag_end == std::string::npos || text[tag_end - 1] == '/') return std::nullopt;
    const std::size_t content = tag_end + 1;
    const std::size_t content_end = text.find('<', content);
    if (content_end == std::string::npos) return std::nullopt;
    const std::string_view data = std::string_view(text).substr(content, content_end - content);
    const std::size_t first = data.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return std::nullopt;
    const std::size_t last = data.find_last_not_of(" \t\r\n");
    if (data.substr(first, last - first + 1) != expected) return std::nullopt;
    return Fix{std::move(description), {TextEdit{content + first, expected.size(), std::move(replacement)}}};
}

}  // namespace esi::rules
