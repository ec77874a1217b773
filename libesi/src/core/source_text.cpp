#include "esi/source_text.hpp"

#include <algorithm>
#include <cstring>

namespace esi {

SourceText::SourceText(std::string path, std::string utf8) : path_(std::move(path)), text_(std::move(utf8)) {
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
}

std::uint32_t SourceText::line_of(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
    return static_cast<std::uint32_t>(it - line_starts_.begin());
}

std::uint32_t SourceText::code_points(std::size_t from, std::size_t to) const {
    std::uint32_t count = 0;
    for (std::size_t i = from; i < to && i < text_.size(); ++i) {
        // Skip UTF-8 continuation bytes.
        if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++count;
    }
    return count;
}

SourcePos SourceText::position_of(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const std::uint32_t line = line_of(offset);
    return SourcePos{line, code_points(line_start(line), offset) + 1};
}

SourcePos PositionCursor::position_of(std::size_t offset) {
    const std::string& text = source_.text();
    offset = std::min(offset, text.size());
    SourcePos pos;
    if (offset >= last_offset_) {
        // Walk forward from the previous position: newlines in between move the line.
        const char* begin = text.data();
        const char* p = begin + last_offset_;
        const char* end = begin + offset;
        std::uint32_t line = last_.line;
        const char* line_begin = nullptr;
        while (p < end) {
            const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
            if (!nl) break;
            ++line;
            p = static_cast<const char*>(nl) + 1;
            line_begin = p;
        }
        pos.line = line;
        pos.column = line_begin ? source_.code_points(static_cast<std::size_t>(line_begin - begin), offset) + 1
                                : last_.column + source_.code_points(last_offset_, offset);
    } else {
        pos = source_.position_of(offset);
    }
    last_offset_ = offset;
    last_ = pos;
    return pos;
}

std::string_view SourceText::line(std::uint32_t line_number) const {
    if (line_number == 0 || line_number > line_starts_.size()) return {};
    const std::size_t start = line_starts_[line_number - 1];
    std::size_t end = line_number < line_starts_.size() ? line_starts_[line_number] : text_.size();
    while (end > start && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
    return std::string_view(text_).substr(start, end - start);
}

}  // namespace esi
