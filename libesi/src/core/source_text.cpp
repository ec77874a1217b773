#include "esi/source_text.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

SourceText::SourceText(std::string path, std::string utf8) : path_(std::move(path)), owned_(std::move(utf8)), text_(owned_) {}

SourceText::SourceText(std::string path, FileBytes bytes, std::size_t offset)
    : path_(std::move(path)), bytes_(std::move(bytes)), text_(bytes_.view().substr(offset)) {}

namespace {

// Appends the offset after every '\n' in text[0, end) to `starts`. Lines are short (25 to 40
// bytes in vendor files), so a memchr call per line spent most of its ~55 instructions on the
// call and its set-up; comparing 16 bytes at a time and taking the newlines from the bit mask
// costs a few instructions per block plus two per line.
void append_line_starts(const char* text, std::size_t end, LineStartList& starts) {
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128i newline = _mm_set1_epi8('\n');
    for (; i + 16 <= end; i += 16) {
        auto mask = static_cast<unsigned>(
            _mm_movemask_epi8(_mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(text + i)), newline)));
        while (mask != 0) {
            starts.push_back(static_cast<std::uint32_t>(i + static_cast<std::size_t>(__builtin_ctz(mask)) + 1));
            mask &= mask - 1;
        }
    }
#endif
    for (; i < end; ++i)
        if (text[i] == '\n') starts.push_back(static_cast<std::uint32_t>(i + 1));
}

}  // namespace

const LineStartList& SourceText::line_starts() const {
    static_assert(std::is_same_v<LineStart, std::uint32_t>);
    std::call_once(index_once_, [this] {
        // Vendor files have lines of 25 to 40 bytes; the index is trimmed to size afterwards, as
        // it lives as long as the document.
        line_starts_.reserve(text_.size() / 24 + 1);
        line_starts_.push_back(0);
        const std::size_t end = std::min<std::size_t>(text_.size(), std::numeric_limits<LineStart>::max());
        append_line_starts(text_.data(), end, line_starts_);
        line_starts_.shrink_to_fit();
    });
    return line_starts_;
}

void SourceText::adopt_line_starts(LineStartList starts) const {
    std::call_once(index_once_, [&] { line_starts_ = std::move(starts); });
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
    return static_cast<std::uint32_t>(count_code_points(text_.substr(from, to - from)));
}

SourcePos SourceText::position_of(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const std::uint32_t line = line_of(offset);
    return SourcePos{line, code_points(line_start(line), offset) + 1};
}

namespace {

// Code points in text[begin, offset). Before an element there is indentation, and after the
// previous element on its line a few bytes of text or markup: the span is checked for non-ASCII
// eight bytes at a time here, inline, the last bytes with one load of the eight bytes ending at
// the offset (it may reach before `begin`, never before the text). Only a span that holds
// non-ASCII is counted by count_code_points; a call per position cost more than the count.
std::size_t columns_between(std::string_view text, std::size_t begin, std::size_t offset) {
    const std::size_t n = offset - begin;
    if (n == 0) return 0;
    if constexpr (std::endian::native == std::endian::little) {
        if (offset >= 8) {
            const char* p = text.data() + begin;
            const char* const end = text.data() + offset;
            std::uint64_t any_high = 0;
            for (; end - p > 8; p += 8) any_high |= load8(p) & high_bits;
            const auto rest = static_cast<unsigned>(end - p);  // 1..8 bytes
            const std::uint64_t last_rest_bytes = ~std::uint64_t{0} << (64 - 8 * rest);  // the highest addresses
            any_high |= load8(end - 8) & last_rest_bytes & high_bits;
            if (any_high == 0) return n;
        }
    }
    return count_code_points(text.substr(begin, n));
}

}  // namespace

PositionCursor::PositionCursor(const SourceText& source) : source_(source), line_starts_(source.line_starts()) {}

SourcePos PositionCursor::position_of(std::size_t offset) {
    // The reader asks for every element's position, in document order, mostly a line or two
    // after the previous one: the line comes from stepping through the line index (which the
    // quoting of diagnostics needs anyway) and the column from the few bytes before the offset.
    // Walking the text itself with memchr cost about 180 instructions a position, this ~50.
    const std::string_view text = source_.text();
    offset = std::min(offset, text.size());
    const std::size_t lines = line_starts_.size();
    std::size_t line = line_;
    if (line_starts_[line] > offset) {
        line = source_.line_of(offset) - 1;  // backwards: search
    } else {
        for (int steps = 0; line + 1 < lines && line_starts_[line + 1] <= offset; ++line) {
            if (++steps == 64) {  // far ahead: search
                line = source_.line_of(offset) - 1;
                break;
            }
        }
    }
    // On the line of the previous offset, count on from there: a minified file is one long line.
    const bool same_line = line == line_ && offset >= last_offset_;
    const std::size_t begin = same_line ? last_offset_ : line_starts_[line];
    const auto counted = static_cast<std::uint32_t>(columns_between(text, begin, offset));
    const std::uint32_t column = same_line ? last_column_ + counted : counted + 1;
    line_ = line;
    last_offset_ = offset;
    last_column_ = column;
    return SourcePos{static_cast<std::uint32_t>(line + 1), column};
}

std::string_view SourceText::line(std::uint32_t line_number) const {
    const auto& starts = line_starts();
    if (line_number == 0 || line_number > starts.size()) return {};
    const std::size_t start = starts[line_number - 1];
    std::size_t end = line_number < starts.size() ? starts[line_number] : text_.size();
    while (end > start && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
    return text_.substr(start, end - start);
}

}  // namespace esi
