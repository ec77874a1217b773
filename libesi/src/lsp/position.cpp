#include "esi/lsp/position.hpp"

#include <algorithm>
#include <cstring>

namespace esi::lsp {

namespace {

// The byte offset where 0-based `line` starts, or npos when the text has fewer lines.
std::size_t line_start(std::string_view text, std::uint32_t line) {
    std::size_t at = 0;
    for (std::uint32_t i = 0; i < line; ++i) {
        const void* newline = std::memchr(text.data() + at, '\n', text.size() - at);
        if (!newline) return std::string_view::npos;
        at = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
    }
    return at;
}

// Bytes of the UTF-8 sequence a lead byte starts (1 for stray continuation bytes, which the
// decoder would have replaced: counted as one character each).
std::size_t sequence_length(unsigned char lead) {
    if (lead < 0xC0) return 1;
    if (lead < 0xE0) return 2;
    if (lead < 0xF0) return 3;
    return 4;
}

std::size_t units_of(std::size_t sequence) { return sequence == 4 ? 2 : 1; }

bool ascii8(std::string_view text, std::size_t at) {
    std::uint64_t chunk = 0;
    std::memcpy(&chunk, text.data() + at, 8);
    return (chunk & 0x8080808080808080ull) == 0;
}

// From `at`, past `count` characters, counting a character outside the BMP as `wide` (2 for
// UTF-16 units, 1 for code points); never past `end`. Eight ASCII bytes at a time.
std::size_t skip(std::string_view text, std::size_t at, std::size_t end, std::uint64_t count, std::uint64_t wide) {
    while (at < end && count > 0) {
        if (count >= 8 && at + 8 <= end && ascii8(text, at)) {
            at += 8;
            count -= 8;
            continue;
        }
        const std::size_t n = sequence_length(static_cast<unsigned char>(text[at]));
        count -= std::min<std::uint64_t>(count, n == 4 ? wide : 1);
        at += n;
    }
    return std::min(at, end);
}

}  // namespace

std::size_t utf16_length(std::string_view utf8) {
    std::size_t units = 0;
    std::size_t i = 0;
    while (i < utf8.size()) {
        // Eight ASCII bytes at a time: a vendor file is almost all ASCII, and a catalogue written
        // on one line puts every finding a megabyte from its line start.
        if (i + 8 <= utf8.size() && ascii8(utf8, i)) {
            units += 8;
            i += 8;
            continue;
        }
        const std::size_t n = sequence_length(static_cast<unsigned char>(utf8[i]));
        units += units_of(n);
        i += n;
    }
    return units;
}

std::size_t offset_of(std::string_view text, Position position) {
    const std::size_t start = line_start(text, position.line);
    if (start == std::string_view::npos) return text.size();
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    if (end > start && text[end - 1] == '\r') --end;
    return skip(text, start, end, position.character, 2);
}

Position position_of(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    Position position;
    std::size_t start = 0;
    for (;;) {
        const void* newline = std::memchr(text.data() + start, '\n', offset - start);
        if (!newline) break;
        start = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
        ++position.line;
    }
    position.character = static_cast<std::uint32_t>(utf16_length(text.substr(start, offset - start)));
    return position;
}

Position position_of(std::string_view text, SourcePos pos) {
    if (!pos.known()) return {};
    const std::uint32_t line = pos.line - 1;
    const std::size_t start = line_start(text, line);
    if (start == std::string_view::npos) return position_of(text, text.size());
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::size_t at = skip(text, start, end, pos.column > 0 ? pos.column - 1 : 0, 1);
    return Position{line, static_cast<std::uint32_t>(utf16_length(text.substr(start, at - start)))};
}

LineIndex::LineIndex(std::string_view text) : text_(text) {
    starts_.push_back(0);
    for (std::size_t at = 0;;) {
        const void* newline = std::memchr(text.data() + at, '\n', text.size() - at);
        if (!newline) break;
        at = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
        starts_.push_back(at);
    }
}

std::size_t LineIndex::offset_of(Position position) const {
    if (position.line >= starts_.size()) return text_.size();
    const std::size_t start = starts_[position.line];
    return start + lsp::offset_of(text_.substr(start), {0, position.character});
}

Position LineIndex::position_of(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const auto after = std::upper_bound(starts_.begin(), starts_.end(), offset);
    const auto line = static_cast<std::uint32_t>(after - starts_.begin() - 1);
    const std::size_t start = starts_[line];
    return {line, static_cast<std::uint32_t>(utf16_length(text_.substr(start, offset - start)))};
}

Position LineIndex::position_of(SourcePos pos) const {
    if (!pos.known()) return {};
    if (pos.line - 1 >= starts_.size()) return position_of(text_.size());
    const std::size_t start = starts_[pos.line - 1];
    Position position = lsp::position_of(text_.substr(start), SourcePos{1, pos.column});
    position.line = pos.line - 1;
    return position;
}

std::size_t LineIndex::offset_of(SourcePos pos) const {
    if (!pos.known()) return 0;
    if (pos.line - 1 >= starts_.size()) return text_.size();
    const std::size_t start = starts_[pos.line - 1];
    std::size_t end = text_.find('\n', start);
    if (end == std::string_view::npos) end = text_.size();
    return skip(text_, start, end, pos.column > 0 ? pos.column - 1 : 0, 1);
}

}  // namespace esi::lsp
