// Hover, definition, references and the outline on the bundled ESI sample.

#include <gtest/gtest.h>

#include "navigate/navigate_test_support.hpp"
#include "support/test_support.hpp"

namespace esi::navigate {
namespace {

using test::at;
using test::range_of;
using test::token_range;

class XmlNavigation : public ::testing::Test {
protected:
    void SetUp() override {
        path = (esi::test::source_dir() / "samples/esi/example-digital-io.xml").string();
        text = esi::test::read_text(path);
        index = build_index(text, path);
    }
    std::string path;
    std::string text;
    IndexPtr index;
};

TEST_F(XmlNavigation, HoverOnPdoEntryIndexShowsTheObject) {
    // The object's Index is the first "<Index>#x7000" of the file, the RxPdo's entry the second.
    const auto result = hover(*index, at(text, "<Index>#x7000", 1, 9));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->range, token_range(text, "<Index>#x7000", "#x7000", 1));
    EXPECT_EQ(result->markdown,
              "**#x7000 Digital outputs**\n\n- type: `USINT`\n- size: 8 bits\n- access: rw\n- PDO mapping: R\n"
              "- default: `0`\n");
}

TEST_F(XmlNavigation, HoverRangeIsInUtf16Units) {
    const auto result = hover(*index, at(text, "<Index>#x7000", 1, 7));
    ASSERT_TRUE(result);
    // Line 180 of the file, the token after 12 spaces and "<Index>".
    EXPECT_EQ(result->range, (Range{{179, 19}, {179, 25}}));
}

TEST_F(XmlNavigation, DefinitionOfPdoEntryIsTheDictionaryObject) {
    const auto found = definition(*index, at(text, "<Index>#x7000", 1, 9));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].path, path);
    EXPECT_EQ(found[0].range, (Range{{158, 23}, {158, 29}}));
    EXPECT_EQ(found[0].range, token_range(text, "<Index>#x7000", "#x7000", 0));
}

TEST_F(XmlNavigation, ReferencesOfAnObjectAreItsPdoEntriesAndMappings) {
    // In document order: 0x1600's default mapping entry, the object itself, the RxPdo's entry.
    const auto with = references(*index, at(text, "<Index>#x7000", 0, 7), true);
    ASSERT_EQ(with.size(), 3u);
    EXPECT_EQ(with[0].range, token_range(text, "#x70000008", "#x70000008"));
    EXPECT_EQ(with[1].range, token_range(text, "<Index>#x7000", "#x7000", 0));
    EXPECT_EQ(with[2].range, token_range(text, "<Index>#x7000", "#x7000", 1));
    const auto without = references(*index, at(text, "<Index>#x7000", 0, 7), false);
    ASSERT_EQ(without.size(), 2u);
    EXPECT_EQ(without[1].range, token_range(text, "<Index>#x7000", "#x7000", 1));
}

TEST_F(XmlNavigation, DataTypeNameGoesToItsDefinitionAndShowsItsLayout) {
    const auto found = definition(*index, at(text, "<Type>DT1018", 0, 6));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, range_of(text, "DT1018", 0));
    const auto result = hover(*index, at(text, "<Type>DT1018", 0, 8));
    ASSERT_TRUE(result);
    EXPECT_NE(result->markdown.find("**DataType DT1018**: 144 bits"), std::string::npos) << result->markdown;
    EXPECT_NE(result->markdown.find("| 1 | Vendor ID | UDINT | 32 | 16 |"), std::string::npos) << result->markdown;
    // References of DT1600: its Name and the Type of #x1600 and #x1A00.
    const auto uses = references(*index, at(text, "<Name>DT1600", 0, 6), true);
    ASSERT_EQ(uses.size(), 3u);
    EXPECT_EQ(uses[0].range, range_of(text, "DT1600", 0));
}

TEST_F(XmlNavigation, BasicTypeWithoutDataTypeElementShowsTheTable) {
    // USINT is defined in this file; UDINT of #x1000 too. A basic type without a DataType
    // element is described from the library's type table.
    const std::string small = "<EtherCATInfo><Descriptions><Devices><Device><Type>D</Type><Profile><Dictionary><Objects>"
                              "<Object><Index>#x2000</Index><Name>n</Name><Type>UINT</Type><BitSize>16</BitSize></Object>"
                              "</Objects></Dictionary></Profile></Device></Devices></Descriptions></EtherCATInfo>";
    const auto local = build_index(small, "small.xml");
    const auto result = hover(*local, at(small, "UINT"));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown, "**UINT** (UNSIGNED16, 0x0006): 16 bits\n");
}

TEST_F(XmlNavigation, HoverOnPdoShowsSizeAndSm) {
    const auto result = hover(*index, at(text, "<Index>#x1600</Index>\n          <Name>Outputs", 0, 8));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown,
              "**RxPdo #x1600 Outputs**\n\n- size: 8 bits (1 byte)\n- entries: 1\n- assigned to: SM2 (Outputs)\n");
}

TEST_F(XmlNavigation, HoverOnSmShowsRoleAddressAndMapping) {
    const auto result = hover(*index, at(text, "\">Outputs</Sm>", 0, 3));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown,
              "**SM2 Outputs** (process data outputs, master to device)\n\n- start address: #x1100\n"
              "- default size: 1 byte\n- control byte: #x64\n- enable: 1\n- mapped by default: 8 bits (1 byte)\n"
              "  - RxPdo #x1600 Outputs (8 bits)\n");
}

TEST_F(XmlNavigation, PdoSmAttributeGoesToTheSm) {
    const auto found = definition(*index, at(text, "Sm=\"3\"", 0, 4));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, token_range(text, ">Inputs</Sm>", "Inputs"));
}

TEST_F(XmlNavigation, OutlineListsDeviceSmsPdosDataTypesObjects) {
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 1u);
    const Symbol& device = symbols[0];
    EXPECT_EQ(device.kind, SymbolKind::device);
    EXPECT_EQ(device.range.start, at(text, "<Device "));
    EXPECT_EQ(device.range.end, LineMap(text).position_of(text.find("</Device>") + 9));
    std::vector<std::string> names;
    for (const auto& child : device.children) names.push_back(child.name);
    const std::vector<std::string> expected = {
        "SM0", "SM1", "SM2", "SM3", "RxPdo #x1600", "TxPdo #x1A00", "USINT", "UINT", "UDINT", "DT1018", "DT1600",
        "DT1C00ARR", "DT1C00", "DT1C12ARR", "DT1C12", "#x1000", "#x1018", "#x1600", "#x1A00", "#x1C00", "#x1C12",
        "#x1C13", "#x6000", "#x7000"};
    EXPECT_EQ(names, expected);
    const Symbol& rx = device.children[4];
    EXPECT_EQ(rx.detail, "Outputs");
    ASSERT_EQ(rx.children.size(), 1u);
    EXPECT_EQ(rx.children[0].name, "#x7000:00");
    EXPECT_EQ(rx.children[0].detail, "Digital outputs");
    EXPECT_EQ(device.children.back().detail, "Digital outputs");
    EXPECT_EQ(device.children.back().selection_range, token_range(text, "<Index>#x7000", "#x7000", 0));
}

TEST_F(XmlNavigation, DictionaryMappingAndAssignmentDefaultsAreReferences) {
    // 0x1600's sub-item 1 maps #x7000:00 (8 bits); 0x1C12's sub-item 1 assigns PDO #x1600.
    const auto object = definition(*index, at(text, "#x70000008", 0, 3));
    ASSERT_EQ(object.size(), 1u);
    EXPECT_EQ(object[0].range, token_range(text, "<Index>#x7000", "#x7000", 0));
    const auto pdo = definition(*index, at(text, "<DefaultValue>#x1600", 0, 16));
    ASSERT_EQ(pdo.size(), 1u);
    EXPECT_EQ(pdo[0].range, token_range(text, "<Index>#x1600</Index>\n          <Name>Outputs", "#x1600"));
    const auto result = hover(*index, at(text, "<DefaultValue>#x1A00", 0, 16));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown.substr(0, 24), "**TxPdo #x1A00 Inputs**\n");
    // The count in sub-index 0 is no reference.
    EXPECT_FALSE(hover(*index, at(text, "<SubItem><Name>Number of entries</Name><Info><DefaultValue>1", 2, 59)));
}

TEST_F(XmlNavigation, NothingUnderTheCursorGivesNothing) {
    const Position on_tag = at(text, "<Eeprom>", 0, 2);
    EXPECT_FALSE(hover(*index, on_tag));
    EXPECT_TRUE(definition(*index, on_tag).empty());
    EXPECT_TRUE(references(*index, on_tag, true).empty());
}

}  // namespace
}  // namespace esi::navigate
