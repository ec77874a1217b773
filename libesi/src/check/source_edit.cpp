#include "check/source_edit.hpp"

#include "esi/source_text.hpp"

namespace esi::rules {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// The byte offset of the '<' at `element`; npos when the document has no source text there.
std::size_t offset_of(const EsiDocument& document, SourcePos element) {
    if (!document.source || !element.known() || element.line > document.source->line_count()) return std::string::npos;
    const SourceText& source = *document.source;
    const std::string_view text = source.text();
    // The column counts code points: walk them to the byte offset.
    std::size_t at = source.line_start(element.line);
    for (std::uint32_t column = 1; column < element.column && at < text.size(); ++column) {
        ++at;
        while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
    }
    if (at >= text.size() || text[at] != '<') return std::string::npos;
    return at;
}

// The offset just past the '>' of the tag starting at `at` (quoted values may hold '>'); npos
// when the tag does not end.
std::size_t tag_end(std::string_view text, std::size_t at) {
    char quote = 0;
    for (std::size_t i = at + 1; i < text.size(); ++i) {
        const char c = text[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '>') {
            return i + 1;
        }
    }
    return std::string_view::npos;
}

// The offset just past the end of the element starting at `at`: its end tag, or its start tag
// when it is empty. Comments, CDATA sections and processing instructions inside are skipped whole.
std::size_t element_end(std::string_view text, std::size_t at) {
    std::size_t end = tag_end(text, at);
    if (end == std::string_view::npos || text[end - 2] == '/') return end;
    int depth = 1;
    while (depth > 0) {
        const std::size_t open = text.find('<', end);
        if (open == std::string_view::npos) return open;
        const std::string_view rest = text.substr(open);
        std::string_view closer;
        if (rest.starts_with("<!--")) closer = "-->";
        else if (rest.starts_with("<![CDATA[")) closer = "]]>";
        else if (rest.starts_with("<?")) closer = "?>";
        if (!closer.empty()) {
            const std::size_t close = text.find(closer, open);
            if (close == std::string_view::npos) return close;
            end = close + closer.size();
            continue;
        }
        end = tag_end(text, open);
        if (end == std::string_view::npos) return end;
        if (rest.starts_with("</")) --depth;
        else if (text[end - 2] != '/') ++depth;
    }
    return end;
}

}  // namespace

std::optional<Fix> replace_element_text(const EsiDocument& document, SourcePos element, std::string_view expected,
                                        std::string replacement, std::string description) {
    const std::size_t at = offset_of(document, element);
    if (at == std::string::npos || expected.empty()) return std::nullopt;
    const std::string_view text = document.source->text();
    const std::size_t end = tag_end(text, at);
    if (end == std::string::npos || text[end - 2] == '/') return std::nullopt;
    const std::size_t content = end;
    const std::size_t content_end = text.find('<', content);
    if (content_end == std::string::npos) return std::nullopt;
    const std::string_view data = std::string_view(text).substr(content, content_end - content);
    const std::size_t first = data.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return std::nullopt;
    const std::size_t last = data.find_last_not_of(" \t\r\n");
    if (data.substr(first, last - first + 1) != expected) return std::nullopt;
    return Fix{std::move(description), {TextEdit{content + first, expected.size(), std::move(replacement)}}};
}

std::optional<Fix> remove_attribute(const EsiDocument& document, SourcePos element, std::string_view name, std::string description) {
    const std::size_t at = offset_of(document, element);
    if (at == std::string::npos || name.empty()) return std::nullopt;
    const std::string_view text = document.source->text();
    const std::size_t end = tag_end(text, at);
    if (end == std::string_view::npos) return std::nullopt;
    // Walk the attributes: blanks, name, blanks, '=', blanks, quoted value.
    std::size_t i = at + 1;
    while (i < end && !is_blank(text[i]) && text[i] != '>' && text[i] != '/') ++i;  // the element's name
    while (i < end) {
        const std::size_t blanks = i;
        while (i < end && is_blank(text[i])) ++i;
        if (i == blanks) return std::nullopt;  // attributes are separated by blanks
        const std::size_t name_start = i;
        while (i < end && !is_blank(text[i]) && text[i] != '=' && text[i] != '>' && text[i] != '/') ++i;
        if (i == name_start) return std::nullopt;  // the end of the tag: not there
        const std::string_view attribute = text.substr(name_start, i - name_start);
        while (i < end && is_blank(text[i])) ++i;
        if (i >= end || text[i] != '=') return std::nullopt;
        ++i;
        while (i < end && is_blank(text[i])) ++i;
        if (i >= end || (text[i] != '"' && text[i] != '\'')) return std::nullopt;
        const std::size_t close = text.find(text[i], i + 1);
        if (close == std::string_view::npos || close >= end) return std::nullopt;
        i = close + 1;
        if (attribute == name) return Fix{std::move(description), {TextEdit{blanks, i - blanks, ""}}};
    }
    return std::nullopt;
}

std::optional<Fix> remove_identical_copy(const EsiDocument& document, SourcePos original, SourcePos copy, std::string description) {
    const std::size_t first = offset_of(document, original);
    const std::size_t second = offset_of(document, copy);
    if (first == std::string::npos || second == std::string::npos || first == second) return std::nullopt;
    const std::string_view text = document.source->text();
    const std::size_t first_end = element_end(text, first);
    const std::size_t second_end = element_end(text, second);
    if (first_end == std::string_view::npos || second_end == std::string_view::npos) return std::nullopt;
    if (text.substr(first, first_end - first) != text.substr(second, second_end - second)) return std::nullopt;
    std::size_t from = second;
    std::size_t to = second_end;
    // Alone on its lines: only blanks before it on its first line and after it on its last.
    std::size_t line_start = from;
    while (line_start > 0 && (text[line_start - 1] == ' ' || text[line_start - 1] == '\t')) --line_start;
    std::size_t line_end = to;
    while (line_end < text.size() && (text[line_end] == ' ' || text[line_end] == '\t')) ++line_end;
    const bool starts_line = line_start == 0 || text[line_start - 1] == '\n';
    const bool ends_line = line_end == text.size() || text[line_end] == '\n' || text[line_end] == '\r';
    if (starts_line && ends_line) {
        from = line_start;
        to = line_end;
        if (to < text.size() && text[to] == '\r') ++to;
        if (to < text.size() && text[to] == '\n') ++to;
    }
    return Fix{std::move(description), {TextEdit{from, to - from, ""}}};
}

}  // namespace esi::rules
