// LSP positions (UTF-16 code units) against UTF-8 byte offsets.

#include <gtest/gtest.h>

#include "esi/navigate/position.hpp"

namespace esi::navigate {
namespace {

TEST(LineMap, AsciiOffsetsAreCharacters) {
    const std::string text = "ab\ncd\n";
    const LineMap lines(text);
    EXPECT_EQ(lines.line_count(), 3u);
    EXPECT_EQ(lines.position_of(4), (Position{1, 1}));
    EXPECT_EQ(lines.offset_of({1, 1}), 4u);
    EXPECT_EQ(lines.offset_of({2, 0}), 6u);
}

TEST(LineMap, NonAsciiCountsUtf16CodeUnits) {
    // "ä" is 2 bytes and 1 unit, "€" 3 bytes and 1 unit, "😀" 4 bytes and 2 units (a surrogate pair).
    const std::string text = "<Name>\xC3\xA4\xE2\x82\xAC\xF0\x9F\x98\x80x</Name>";
    const LineMap lines(text);
    EXPECT_EQ(lines.position_of(6), (Position{0, 6}));
    EXPECT_EQ(lines.position_of(8), (Position{0, 7}));   // after ä
    EXPECT_EQ(lines.position_of(11), (Position{0, 8}));  // after €
    EXPECT_EQ(lines.position_of(15), (Position{0, 10})); // after 😀
    EXPECT_EQ(lines.offset_of({0, 7}), 8u);
    EXPECT_EQ(lines.offset_of({0, 8}), 11u);
    EXPECT_EQ(lines.offset_of({0, 10}), 15u);
    // Between the two halves of the surrogate pair: the start of the character.
    EXPECT_EQ(lines.offset_of({0, 9}), 11u);
    // A byte inside a multi-byte sequence counts as the character's start.
    EXPECT_EQ(lines.position_of(12), (Position{0, 8}));
}

TEST(LineMap, CrLfAndLoneCrEndLines) {
    const std::string text = "a\r\nb\rc\nd";
    const LineMap lines(text);
    EXPECT_EQ(lines.line_count(), 4u);
    EXPECT_EQ(lines.position_of(3), (Position{1, 0}));
    EXPECT_EQ(lines.position_of(5), (Position{2, 0}));
    EXPECT_EQ(lines.offset_of({3, 0}), 7u);
    // A character past the end of the line means the line's end, before its terminator.
    EXPECT_EQ(lines.offset_of({0, 99}), 1u);
}

TEST(LineMap, PositionsPastTheEnd) {
    const std::string text = "abc";
    const LineMap lines(text);
    EXPECT_FALSE(lines.offset_of({1, 0}).has_value());
    EXPECT_EQ(lines.position_of(999), (Position{0, 3}));
    const LineMap empty(std::string_view{});
    EXPECT_EQ(empty.offset_of({0, 5}), 0u);
    EXPECT_FALSE(empty.offset_of({7, 0}).has_value());
}

TEST(LineMap, LongLinesAgreeWithACountFromTheLineStart) {
    // A single-line file (some vendor files are): positions come from checkpoints inside the line.
    std::string text = "<a>\n";
    for (int i = 0; i < 3000; ++i) text += i % 7 == 0 ? "\xC3\xA4" : i % 11 == 0 ? "\xF0\x9F\x98\x80" : "x";
    text += "\nend";
    const LineMap lines(text);
    std::uint32_t units = 0;
    std::size_t offset = 4;
    while (offset < text.size() - 4) {
        ASSERT_EQ(lines.position_of(offset), (Position{1, units})) << offset;
        ASSERT_EQ(lines.offset_of(Position{1, units}), offset) << units;
        const unsigned char lead = static_cast<unsigned char>(text[offset]);
        const std::size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        units += length == 4 ? 2 : 1;
        offset += length;
    }
    EXPECT_EQ(lines.position_of(text.size()), (Position{2, 3}));
    EXPECT_EQ(lines.offset_of(Position{1, 99999}), text.size() - 4);
}

}  // namespace
}  // namespace esi::navigate
