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
}

std::size_t LineMap::line_end(std::size_t line) const {
    std::size_t end = line + 1 < starts_.size() ? starts_[line + 1] : text_.size();
    if (end > starts_[line] && text_[end - 1] == '\n') --end;
    if (end > starts_[line] && text_[end - 1] == '\r') --end;
    return end;
}

std::optional<std::size_t> LineMap::offset_of(Position position) const {
    if (position.line >= starts_.size()) return std::nullopt;
    std::size_t offset = starts_[position.line];
    const std::size_t end = line_end(position.line);
    std::uint32_t units = 0;
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
    std::size_t i = starts_[line];
    const std::size_t end = std::min(offset, line_end(line));
    std::uint32_t units = 0;
    while (i < end) {
        const std::size_t length = sequence_length(static_cast<unsigned char>(text_[i]));
        if (i + length > end && i + length > offset) break;  // offset inside this character
        units += length == 4 ? 2 : 1;
        i += length;
    }
    return Position{static_cast<std::uint32_t>(line), units};
}

}  // namespace esi::navigate
