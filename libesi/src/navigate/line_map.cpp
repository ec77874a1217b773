// UTF-8 byte offsets <-> LSP positions (UTF-16 code units).

#include "esi/navigate/position.hpp"

#include <algorithm>
#include <cstring>

namespace esi::navigate {

namespace {

// Length in bytes of the UTF-8 sequence a lead byte starts; 1 for a stray continuation or an
// invalid lead, so that broken text still advances one byte at a time.
std::size_t sequence_length(unsigned char lead) {
    if (lead < 0xC0) return 1;
    if (lead < 0xE0) return 2;
    if (lead < 0xF0) return 3;
    if (lead < 0xF8) return 4;
    return 1;
}

}  // namespace

LineMap::LineMap(std::string_view text) : text_(text) {
    starts_.push_back(0);
    const char* data = text.data();
    const std::size_t size = text.size();
    std::size_t i = 0;
    while (i < size) {
        // Most of an ESI file is not a line break: jump to the next candidate.
        const void* lf = std::memchr(data + i, '\n', size - i);
        const std::size_t next_lf = lf ? static_cast<std::size_t>(static_cast<const char*>(lf) - data) : size;
        const void* cr = std::memchr(data + i, '\r', next_lf - i);
        if (cr) {
            const auto at = static_cast<std::size_t>(static_cast<const char*>(cr) - data);
            i = at + 1 < size && data[at + 1] == '\n' ? at + 2 : at + 1;
        } else if (lf) {
            i = next_lf + 1;
        } else {
            break;
        }
        starts_.push_back(static_cast<std::uint32_t>(i));
    }
    for (std::size_t line = 0; line < starts_.size(); ++line) {
        const std::size_t end = line_end(line);
        std::size_t at = starts_[line];
        if (end - at <= checkpoint_spacing) continue;
        std::uint32_t units = 0;
        std::size_t next = at + checkpoint_spacing;
        while (at < end) {
            if (at >= next) {
                checkpoints_.push_back(Checkpoint{static_cast<std::uint32_t>(at), units});
                next = at + checkpoint_spacing;
            }
            const std::size_t length = std::min(sequence_length(static_cast<unsigned char>(text_[at])), end - at);
            units += length == 4 ? 2 : 1;
            at += length;
        }
    }
}

LineMap::Checkpoint LineMap::start_for_offset(std::size_t line, std::size_t offset) const {
    const Checkpoint line_start{starts_[line], 0};
    if (checkpoints_.empty()) return line_start;
    auto after = std::upper_bound(checkpoints_.begin(), checkpoints_.end(), offset,
                                  [](std::size_t value, const Checkpoint& c) { return value < c.offset; });
    if (after == checkpoints_.begin()) return line_start;
    const Checkpoint& candidate = *(after - 1);
    return candidate.offset >= starts_[line] ? candidate : line_start;
}

LineMap::Checkpoint LineMap::start_for_units(std::size_t line, std::uint32_t units) const {
    const Checkpoint line_start{starts_[line], 0};
    // The line's checkpoints are contiguous, their units increasing.
    auto first = std::lower_bound(checkpoints_.begin(), checkpoints_.end(), std::size_t{starts_[line]},
                                  [](const Checkpoint& c, std::size_t value) { return c.offset < value; });
    auto beyond = std::lower_bound(first, checkpoints_.end(), line_end(line),
                                   [](const Checkpoint& c, std::size_t value) { return c.offset < value; });
    auto last = std::partition_point(first, beyond, [&](const Checkpoint& c) { return c.units <= units; });
    return last == first ? line_start : *(last - 1);
}

std::size_t LineMap::line_end(std::size_t line) const {
    std::size_t end = line + 1 < starts_.size() ? starts_[line + 1] : text_.size();
    if (end > starts_[line] && text_[end - 1] == '\n') --end;
    if (end > starts_[line] && text_[end - 1] == '\r') --end;
    return end;
}

std::optional<std::size_t> LineMap::offset_of(Position position) const {
    if (position.line >= starts_.size()) return std::nullopt;
    const Checkpoint start = start_for_units(position.line, position.character);
    std::size_t offset = start.offset;
    const std::size_t end = line_end(position.line);
    std::uint32_t units = start.units;
    while (offset < end) {
        const std::size_t length = std::min(sequence_length(static_cast<unsigned char>(text_[offset])), end - offset);
        const std::uint32_t width = length == 4 ? 2 : 1;  // beyond the BMP: a surrogate pair
        if (units + width > position.character) break;
        units += width;
        offset += length;
    }
    return offset;
}

Position LineMap::position_of(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const auto after = std::upper_bound(starts_.begin(), starts_.end(), offset);
    const auto line = static_cast<std::size_t>(after - starts_.begin()) - 1;
    const std::size_t end = std::min(offset, line_end(line));
    const Checkpoint start = start_for_offset(line, end);
    std::size_t i = start.offset;
    std::uint32_t units = start.units;
    while (i < end) {
        const std::size_t length = sequence_length(static_cast<unsigned char>(text_[i]));
        if (i + length > end && i + length > offset) break;  // offset inside this character
        units += length == 4 ? 2 : 1;
        i += length;
    }
    return Position{static_cast<std::uint32_t>(line), units};
}

}  // namespace esi::navigate
