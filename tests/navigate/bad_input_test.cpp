// Whatever the editor holds, the index answers: empty results, never a crash.

#include <gtest/gtest.h>

#include "navigate/navigate_test_support.hpp"
#include "support/test_support.hpp"

namespace esi::navigate {
namespace {

void expect_nothing_anywhere(const std::string& text) {
    const auto index = build_index(text, "bad.xml");
    ASSERT_TRUE(index);
    const LineMap lines(text);
    for (std::uint32_t line = 0; line <= lines.line_count() + 1; ++line)
        for (std::uint32_t character : {0u, 1u, 5u, 1000u}) {
            const Position position{line, character};
            EXPECT_FALSE(hover(*index, position));
            EXPECT_TRUE(definition(*index, position).empty());
            EXPECT_TRUE(references(*index, position, true).empty());
            (void)complete(*index, position);
        }
    EXPECT_TRUE(outline(*index).empty());
}

TEST(NavigateBadInput, NotXmlNotYamlEmptyAndBinary) {
    expect_nothing_anywhere("");
    expect_nothing_anywhere("this is not a device description");
    expect_nothing_anywhere("<<<>>>&&&");
    expect_nothing_anywhere(std::string("\0\xFF\xFE<\x01", 5));
    expect_nothing_anywhere("{ unclosed: [ yaml");
    expect_nothing_anywhere("- a\n- b\n");
}

TEST(NavigateBadInput, EveryTruncationOfTheSampleIsSafe) {
    const std::string text = esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml");
    // Cut the file at many points: what parsed before the cut is navigable, nothing crashes.
    for (std::size_t cut = 0; cut < text.size(); cut += 97) {
        const std::string part = text.substr(0, cut);
        const auto index = build_index(part, "cut.xml");
        const LineMap lines(part);
        for (std::uint32_t line = 0; line < lines.line_count() + 2; line += 3) {
            const Position position{line, 20};
            (void)hover(*index, position);
            (void)definition(*index, position);
            (void)references(*index, position, false);
            (void)complete(*index, position);
        }
        (void)outline(*index);
    }
}

TEST(NavigateBadInput, TruncatedFileStillNavigatesWhatParsed) {
    const std::string text = esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml");
    // Cut in the middle of the RxPdo: the dictionary before it is complete.
    const std::string part = text.substr(0, text.find("<SubIndex>0</SubIndex>"));
    const auto index = build_index(part, "cut.xml");
    const auto found = definition(*index, test::at(part, "<Index>#x7000", 1, 8));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, test::token_range(part, "<Index>#x7000", "#x7000", 0));
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 1u);
    EXPECT_EQ(symbols[0].range.end, LineMap(part).position_of(part.size()));
}

TEST(NavigateBadInput, DeepNestingInsideADevice) {
    // pugixml parses any depth; the index must not recurse along it.
    std::string text = "<EtherCATInfo><Descriptions><Devices><Device><Type>D</Type><Sm>Inputs</Sm>";
    for (int i = 0; i < 200000; ++i) text += "<a>";
    for (int i = 0; i < 200000; ++i) text += "</a>";
    text += "</Device></Devices></Descriptions></EtherCATInfo>";
    const auto index = build_index(text, "deep.xml");
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 1u);
    EXPECT_EQ(symbols[0].range.end, LineMap(text).position_of(text.size() - 40));
    EXPECT_TRUE(hover(*index, test::at(text, "Inputs")));
    (void)complete(*index, test::at(text, "<a><a>", 0, 3));
    // Unclosed: every element ends at the end of the text.
    const std::string open = text.substr(0, text.find("</a>"));
    const auto open_index = build_index(open, "open.xml");
    ASSERT_EQ(outline(*open_index).size(), 1u);
    EXPECT_EQ(outline(*open_index)[0].range.end, LineMap(open).position_of(open.size()));
}

TEST(NavigateBadInput, PositionsPastTheEndGiveNothing) {
    const std::string text = esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml");
    const auto index = build_index(text, "x.xml");
    for (const Position position : {Position{100000, 0}, Position{4000000000u, 4000000000u}, Position{224, 0}}) {
        EXPECT_FALSE(hover(*index, position));
        EXPECT_TRUE(definition(*index, position).empty());
        EXPECT_TRUE(references(*index, position, true).empty());
        EXPECT_TRUE(complete(*index, position).empty());
    }
}

}  // namespace
}  // namespace esi::navigate
