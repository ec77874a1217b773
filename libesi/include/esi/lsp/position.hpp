#pragma once
// Positions as the Language Server Protocol counts them: 0-based lines and 0-based columns in
// UTF-16 code units (the protocol's default position encoding), over the document's UTF-8 text.
// A character outside the Basic Multilingual Plane (an emoji in a comment) is two units; ä is one
// unit but two bytes. Lines end at '\n' (a "\r\n" line ends there too), as in esi::SourceText,
// so the lines of lint findings and of the editor agree.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "esi/source_pos.hpp"

namespace esi::lsp {

struct Position {
    std::uint32_t line = 0;
    std::uint32_t character = 0;  // UTF-16 code units from the line start
    friend constexpr auto operator<=>(const Position&, const Position&) = default;
};

struct Range {
    Position start;
    Position end;
};

// The byte offset of a position. Clamped as the protocol asks: a character past the end of its
// line means the line end (before "\r\n"), a line past the last means the end of the text; a
// position inside a surrogate pair moves to the character's end.
[[nodiscard]] std::size_t offset_of(std::string_view text, Position position);

// The position of a byte offset (clamped to the text; an offset inside a UTF-8 sequence counts
// the character as passed).
[[nodiscard]] Position position_of(std::string_view text, std::size_t offset);

// The position of a lint finding's line:column (1-based, the column in code points).
[[nodiscard]] Position position_of(std::string_view text, SourcePos pos);

// The same conversions over many positions of one text: the line starts are found once.
class LineIndex {
public:
    explicit LineIndex(std::string_view text);
    [[nodiscard]] std::size_t offset_of(Position position) const;
    [[nodiscard]] Position position_of(std::size_t offset) const;
    [[nodiscard]] Position position_of(SourcePos pos) const;
    // The byte offset of a lint finding's line:column.
    [[nodiscard]] std::size_t offset_of(SourcePos pos) const;

private:
    std::string_view text_;
    std::vector<std::size_t> starts_;
};

// UTF-16 code units of a UTF-8 text.
[[nodiscard]] std::size_t utf16_length(std::string_view utf8);

}  // namespace esi::lsp
