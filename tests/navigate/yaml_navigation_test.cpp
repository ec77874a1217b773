// Hover, definition, references and the outline on YAML device sources: tokens from the source,
// facts from the derived model.

#include <gtest/gtest.h>

#include "navigate/navigate_test_support.hpp"
#include "support/test_support.hpp"

namespace esi::navigate {
namespace {

using test::at;
using test::token_range;

class YamlNavigation : public ::testing::Test {
protected:
    void load(const std::string& name) {
        path = (esi::test::source_dir() / "samples" / name).string();
        text = esi::test::read_text(path);
        index = build_index(text, path);
    }
    std::string path;
    std::string text;
    IndexPtr index;
};

TEST_F(YamlNavigation, PdoEntryOfASubItemShowsTheDerivedSubItem) {
    load("digital-io-8.yaml");
    const auto result = hover(*index, at(text, "\"0x7000:2\"", 0, 3));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->range, token_range(text, "\"0x7000:2\"", "0x7000:2"));
    EXPECT_EQ(result->markdown,
              "**0x7000:2 Output 2**  \nsub-item of 0x7000 Digital outputs\n\n- type: `BOOL`\n- size: 1 bit\n"
              "- bit offset: 17\n- access: rw\n- PDO mapping: R\n- default: `0`\n");
}

TEST_F(YamlNavigation, PdoEntryGoesToTheEntryKeyOfTheObject) {
    load("digital-io-8.yaml");
    const auto found = definition(*index, at(text, "\"0x7000:2\"", 0, 1));
    ASSERT_EQ(found.size(), 1u);
    // `2:` under 0x7000's entries.
    EXPECT_EQ(found[0].range, token_range(text, "2: { name: Output 2", "2"));
}

TEST_F(YamlNavigation, ObjectReferencesAreItsPdoEntries) {
    load("digital-io-8.yaml");
    const auto uses = references(*index, at(text, "0x6000:\n"), true);
    ASSERT_EQ(uses.size(), 9u);  // the key and eight entries of 0x1A00
    EXPECT_EQ(uses[0].range, token_range(text, "0x6000:\n", "0x6000"));
    EXPECT_EQ(uses[1].range, token_range(text, "\"0x6000:1\"", "0x6000:1"));
    EXPECT_EQ(uses[8].range, token_range(text, "\"0x6000:8\"", "0x6000:8"));
}

TEST_F(YamlNavigation, EntryByNameResolvesToTheObject) {
    load("servo-item-c-series.yaml");
    const auto result = hover(*index, at(text, "entries: [Controlword", 0, 12));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown,
              "**0x6040 Controlword**\n\n- type: `UINT`\n- size: 16 bits\n- access: rw\n- PDO mapping: R\n"
              "- default: `0`\n");
    EXPECT_EQ(result->range, token_range(text, "entries: [Controlword", "Controlword"));
    const auto found = definition(*index, at(text, "object: Modes of operation", 0, 10));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, token_range(text, "0x6060:", "0x6060"));
}

TEST_F(YamlNavigation, PdoShowsTheSmDerivationAssigns) {
    load("servo-item-c-series.yaml");
    const auto result = hover(*index, at(text, "index: 0x1600", 0, 8));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown,
              "**RxPdo 0x1600 Outputs**\n\n- size: 24 bits (3 bytes)\n- entries: 2\n- assigned to: SM2 (Outputs)\n");
}

TEST_F(YamlNavigation, OutlineListsWhatTheSourceWrites) {
    load("digital-io-8.yaml");
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 1u);
    EXPECT_EQ(symbols[0].name, "EX-DIO-8B");
    EXPECT_EQ(symbols[0].selection_range, token_range(text, "type: EX-DIO-8B", "EX-DIO-8B"));
    std::vector<std::string> names;
    for (const auto& child : symbols[0].children) names.push_back(child.name + " " + child.detail);
    // Derived SMs, mapping objects and DataTypes are not in the text: not in the outline.
    const std::vector<std::string> expected = {"RxPdo 0x1600 Outputs", "TxPdo 0x1A00 Inputs", "0x6000 Digital inputs",
                                               "0x7000 Digital outputs", "0x8000 Input filter"};
    EXPECT_EQ(names, expected);
    ASSERT_EQ(symbols[0].children[0].children.size(), 8u);
    EXPECT_EQ(symbols[0].children[0].children[0].name, "0x7000:1");
    EXPECT_EQ(symbols[0].children[0].children[0].detail, "Output 1");
}

TEST_F(YamlNavigation, SourceWithErrorsStillKnowsWrittenIndices) {
    // An entry naming a missing object is an error: nothing is derived, the tree still tells.
    text = "devices:\n  - type: X\n    objects:\n      0x6000: { name: In, type: UINT, access: ro, pdo: tx }\n"
           "    txpdo:\n      - { index: 0x1A00, name: In, entries: [0x6000, 0x6001] }\n";
    index = build_index(text, "x.yaml");
    const auto found = definition(*index, at(text, "entries: [0x6000", 0, 11));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, token_range(text, "0x6000: {", "0x6000"));
    const auto result = hover(*index, at(text, "0x6001", 0, 1));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown, "Object 0x6001 is not in the dictionary of device X.\n");
}

TEST_F(YamlNavigation, WrittenSmsAndPdoSmReferences) {
    text = "vendor: { id: 0x2, name: V }\n"
           "devices:\n"
           "  - type: X\n"
           "    name: X device\n"
           "    product_code: 1\n"
           "    revision: 1\n"
           "    objects:\n"
           "      0x7000: { name: Out, type: UINT, access: rw, pdo: rx }\n"
           "    sms:\n"
           "      - { type: Outputs, address: 0x1100, control_byte: 0x64, size: 2 }\n"
           "      - { type: Inputs, address: 0x1180, control_byte: 0x20 }\n"
           "    rxpdo:\n"
           "      - { index: 0x1600, name: Out, sm: 0, entries: [0x7000] }\n";
    index = build_index(text, "sm.yaml");
    const auto found = definition(*index, at(text, "sm: 0", 0, 4));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, token_range(text, "{ type: Outputs", "Outputs"));
    const auto result = hover(*index, at(text, "type: Outputs", 0, 7));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown,
              "**SM0 Outputs** (process data outputs, master to device)\n\n- start address: 0x1100\n"
              "- default size: 2 bytes\n- control byte: 0x64\n- enable: 1\n- mapped by default: 16 bits (2 bytes)\n"
              "  - RxPdo 0x1600 Out (16 bits)\n");
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 1u);
    ASSERT_GE(symbols[0].children.size(), 2u);
    EXPECT_EQ(symbols[0].children[0].name, "SM0");
    EXPECT_EQ(symbols[0].children[1].name, "SM1");
}

}  // namespace
}  // namespace esi::navigate
