#pragma once
// Positions as the Language Server Protocol counts them: 0-based line and 0-based character in
// UTF-16 code units (LSP's default position encoding), and their conversion to and from byte
// offsets in the UTF-8 text libesi holds. Editors send UTF-16 positions; everything below this
// header works on byte offsets.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace esi::navigate {

struct Position {
    std::uint32_t line = 0;
    std::uint32_t character = 0;  // UTF-16 code units from the start of the line
    friend constexpr bool operator==(const Position&, const Position&) = default;
};

struct Range {
    Position start;
    Position end;  // exclusive
    friend constexpr bool operator==(const Range&, const Range&) = default;
};

// ESI references never cross files, so a location is always in the indexed document; the path is
// the one given to build_index.
struct Location {
    std::string path;
    Range range;
    friend bool operator==(const Location&, const Location&) = default;
};

// Line starts of a UTF-8 text (LF, CRLF and lone CR end a line, as in LSP). The map refers to the
// text it was built from; it must outlive the map.
class LineMap {
public:
    explicit LineMap(std::string_view text);

    // Byte offset of a position. A character past the end of its line means the line's end (the
    // LSP rule); a line past the last one has no offset. A position inside a UTF-16 surrogate pair
    // or a multi-byte sequence goes to the start of that character.
    [[nodiscard]] std::optional<std::size_t> offset_of(Position position) const;
    // Position of a byte offset (clamped to the end of the text); an offset inside a multi-byte
    // sequence counts as the start of that character.
    [[nodiscard]] Position position_of(std::size_t offset) const;
    [[nodiscard]] Range range_of(std::size_t begin, std::size_t end) const {
        return Range{position_of(begin), position_of(end)};
    }
    [[nodiscard]] std::size_t line_count() const { return starts_.size(); }

private:
    // The end of a line's content: before its terminator.
    [[nodiscard]] std::size_t line_end(std::size_t line) const;

    // A point inside a long line whose UTF-16 column is known, so that a position in a
    // single-line multi-MB file costs a short walk from the nearest checkpoint, not from the
    // line's start. Only lines longer than the spacing have them.
    struct Checkpoint {
        std::uint32_t offset;
        std::uint32_t units;  // UTF-16 code units from the start of its line
    };
    static constexpr std::size_t checkpoint_spacing = 1024;

    // The checkpoint of `line` nearest before the offset (or the units), as a starting point.
    [[nodiscard]] Checkpoint start_for_offset(std::size_t line, std::size_t offset) const;
    [[nodiscard]] Checkpoint start_for_units(std::size_t line, std::uint32_t units) const;

    std::string_view text_;
    std::vector<std::uint32_t> starts_;  // inputs are bounded by esi::max_input_bytes (< 4 GiB)
    std::vector<Checkpoint> checkpoints_;  // by offset
};

}  // namespace esi::navigate
