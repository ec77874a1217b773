#include "esi/source_text.hpp"

#include <algorithm>
#include <cstring>

namespace esi {

namespace {

constexpr std::uint64_t high_bits = 0x8080808080808080ull;

std::uint64_t load8(const char* p) {
    std::uint64_t v = 0;
    std::memcpy(&v, p, 8);
    return v;
}

}  // namespace

std::size_t count_code_points(std::string_view text) {
    // Code points = bytes that are not UTF-8 continuation bytes (10xxxxxx); ASCII runs are
    // skipped eight bytes at a time.
    std::size_t count = 0;
    std::size_t i = 0;
    while (i < text.size()) {
        if (i + 8 <= text.size() && (load8(text.data() + i) & high_bits) == 0) {
            count += 8;
            i += 8;
            continue;
        }
        count += (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;
        ++i;
    }
    return count;
}

std::size_t count_newlines(std::string_view text) {
    std::size_t count = 0;
    for (const char* p = text.data(), *end = text.data() + text.size(); p < end; ++count) {
        p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
        if (!p) break;
        ++p;
    }
    return count;
}

SourceText::SourceText(std::string path, std::string utf8) : path_(std::move(path)), text_(std::move(utf8)) {}

const std::vector<std::size_t>& SourceText::line_starts() const {
    std::call_once(index_once_, [this] {
        line_starts_.reserve(text_.size() / 40 + 1);
        line_starts_.push_back(0);
        const char* begin = text_.data();
        const char* end = begin + text_.size();
        for (const char* p = begin; p < end;) {
            const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
            if (!nl) break;
            p = static_cast<const char*>(nl) + 1;
            line_starts_.push_back(static_cast<std::size_t>(p - begin));
        }
    });
    return line_starts_;
}

std::uint32_t SourceText::line_of(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const auto& starts = line_starts();
    const auto it = std::upper_bound(starts.begin(), starts.end(), offset);
    return static_cast<std::uint32_t>(it - starts.begin());
}

std::uint32_t SourceText::code_points(std::size_t from, std::size_t to) const {
    to = std::min(to, text_.size());
    if (from >= to) return 0;
    return static_cast<std::uint32_t>(count_code_points(std::string_view(text_).substr(from, to - from)));
}

SourcePos SourceText::position_of(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const std::uint32_t line = line_of(offset);
    return SourcePos{line, code_points(line_start(line), offset) + 1};
}

SourcePos PositionCursor::position_of(std::size_t offset) {
    const std::string& text = source_.text();
    offset = std::min(offset, text.size());
    if (offset < last_offset_) {
        last_offset_ = offset;
        last_ = source_.position_of(offset);
        return last_;
    }
    // The reader asks for every element's position, some 50 bytes after the previous one,
    // typically one line further and behind a few tabs of indentation. So the last line break
    // before the offset is looked for backwards, byte by byte, noting on the way whether the
    // bytes are ASCII (then the column is a difference of offsets); memchr counts the line
    // breaks before it. This does in ~70 instructions a call what a forward memchr walk plus a
    // code point count did in ~190.
    const char* const from = text.data() + last_offset_;
    const char* const end = text.data() + offset;
    const char* line_begin = end;
    unsigned char high = 0;
    while (line_begin > from && line_begin[-1] != '\n') high |= static_cast<unsigned char>(*--line_begin);
    const auto columns = [&](const char* begin) {
        const auto bytes = static_cast<std::size_t>(end - begin);
        return static_cast<std::uint32_t>(high & 0x80 ? count_code_points(std::string_view(begin, bytes)) : bytes);
    };
    SourcePos pos;
    if (line_begin == from) {
        pos = SourcePos{last_.line, last_.column + columns(from)};
    } else {
        std::uint32_t line = last_.line + 1;  // the break at line_begin[-1]
        const char* const last_break = line_begin - 1;
        for (const char* p = from; p < last_break; ++line) {
            p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(last_break - p)));
            if (!p) break;
            ++p;
        }
        pos = SourcePos{line, 1 + columns(line_begin)};
    }
    last_offset_ = offset;
    last_ = pos;
    return pos;
}

std::string_view SourceText::line(std::uint32_t line_number) const {
    const auto& starts = line_starts();
    if (line_number == 0 || line_number > starts.size()) return {};
    const std::size_t start = starts[line_number - 1];
    std::size_t end = line_number < starts.size() ? starts[line_number] : text_.size();
    while (end > start && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
    return std::string_view(text_).substr(start, end - start);
}

}  // namespace esi
