// Completion in ESI files and YAML sources: object indices, DataType names, element names.

#include <gtest/gtest.h>

#include <algorithm>

#include "navigate/navigate_test_support.hpp"
#include "support/test_support.hpp"

namespace esi::navigate {
namespace {

using test::at;

std::vector<std::string> labels(const std::vector<CompletionItem>& items) {
    std::vector<std::string> out;
    for (const auto& item : items) out.push_back(item.label);
    return out;
}

const CompletionItem* find(const std::vector<CompletionItem>& items, std::string_view label) {
    const auto it = std::find_if(items.begin(), items.end(), [&](const CompletionItem& i) { return i.label == label; });
    return it == items.end() ? nullptr : &*it;
}

std::string sample_xml() { return esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml"); }

TEST(XmlCompletion, PdoEntryIndexOffersTheDeviceObjects) {
    const std::string text = sample_xml();
    const auto index = build_index(text, "x.xml");
    const auto items = complete(*index, at(text, "<Index>#x7000</Index>\n            <SubIndex>", 0, 9));
    const std::vector<std::string> expected = {"#x1000", "#x1018", "#x1600", "#x1A00", "#x1C00",
                                               "#x1C12", "#x1C13", "#x6000", "#x7000"};
    EXPECT_EQ(labels(items), expected);
    const CompletionItem* item = find(items, "#x6000");
    ASSERT_TRUE(item);
    EXPECT_EQ(item->detail, "Digital inputs");
    EXPECT_EQ(item->kind, CompletionKind::object);
    EXPECT_EQ(item->insert_text, "#x6000");
    // The whole value is replaced.
    EXPECT_EQ(item->replace, test::token_range(text, "<Index>#x7000</Index>\n            <SubIndex>", "#x7000"));
}

TEST(XmlCompletion, EmptyIndexWhileTyping) {
    // Not well-formed: the entry is being typed.
    std::string text = sample_xml();
    const std::size_t cut = text.find("<Index>#x7000</Index>\n            <SubIndex>");
    text = text.substr(0, cut) + "<Index>#x";
    const auto index = build_index(text, "x.xml");
    const auto items = complete(*index, LineMap(text).position_of(text.size()));
    ASSERT_EQ(items.size(), 9u);
    EXPECT_EQ(items.back().label, "#x7000");
    EXPECT_EQ(items.back().detail, "Digital outputs");
    EXPECT_EQ(items.back().replace, LineMap(text).range_of(text.size() - 2, text.size()));
}

TEST(XmlCompletion, TypeOffersDataTypesThenBasicTypes) {
    const std::string text = sample_xml();
    const auto index = build_index(text, "x.xml");
    const auto items = complete(*index, at(text, "<Type>DT1018", 0, 7));
    ASSERT_GT(items.size(), 7u);
    const std::vector<std::string> all = labels(items);
    const std::vector<std::string> first(all.begin(), all.begin() + 7);
    const std::vector<std::string> expected = {"USINT", "UINT", "UDINT", "DT1018", "DT1600", "DT1C00ARR", "DT1C00"};
    EXPECT_EQ(first, expected);
    const CompletionItem* bool_item = find(items, "BOOL");
    ASSERT_TRUE(bool_item);
    EXPECT_EQ(bool_item->detail, "BOOLEAN, 1 bit");
    EXPECT_EQ(std::count(all.begin(), all.end(), "UINT"), 1);
}

TEST(XmlCompletion, TagNameOffersTheSchemaChildren) {
    std::string text = sample_xml();
    const std::size_t cut = text.find("<SubIndex>0</SubIndex>");
    text = text.substr(0, cut) + "<B";
    const auto index = build_index(text, "x.xml");
    const auto items = complete(*index, LineMap(text).position_of(text.size()));
    const std::vector<std::string> expected = {"Index", "SubIndex", "BitLen", "Name", "Comment", "DataType"};
    EXPECT_EQ(labels(items), expected);
    EXPECT_EQ(items[2].kind, CompletionKind::element);
    EXPECT_EQ(items[2].insert_text, "BitLen");
    EXPECT_EQ(items[2].replace, LineMap(text).range_of(text.size() - 1, text.size()));
}

TEST(XmlCompletion, BlankInsideAnElementOffersChildElements) {
    const std::string text = sample_xml();
    const auto index = build_index(text, "x.xml");
    // The blank before the Eeprom's first child.
    const auto items = complete(*index, at(text, "<Eeprom>\n", 0, 9));
    ASSERT_FALSE(items.empty());
    EXPECT_EQ(items[0].label, "Data");
    EXPECT_EQ(items[1].insert_text, "<ByteSize></ByteSize>");
    // Same name, other place: Sm under Dc/OpMode holds Pdo.
    const std::string dc = "<EtherCATInfo><Descriptions><Devices><Device><Dc><OpMode><Sm No=\"2\"> </Sm>";
    const auto dc_index = build_index(dc, "dc.xml");
    EXPECT_EQ(labels(complete(*dc_index, LineMap(dc).position_of(dc.size() - 5))), std::vector<std::string>{"Pdo"});
}

TEST(XmlCompletion, NothingInCommentsAttributesOrUnknownPlaces) {
    const std::string text = sample_xml();
    const auto index = build_index(text, "x.xml");
    EXPECT_TRUE(complete(*index, at(text, "StartAddress=\"#x1000\"", 0, 15)).empty());
    EXPECT_TRUE(complete(*index, at(text, "<ByteSize>2048", 0, 12)).empty());
    const std::string commented = "<EtherCATInfo><!-- <Devices><Device><RxPdo><Entry><Index> -->";
    const auto comment_index = build_index(commented, "c.xml");
    EXPECT_TRUE(complete(*comment_index, LineMap(commented).position_of(commented.size() - 5)).empty());
}

TEST(YamlCompletion, EntriesOfferObjectsAndSubItems) {
    const std::string text = esi::test::read_text(esi::test::source_dir() / "samples/digital-io-8.yaml");
    const auto index = build_index(text, "d.yaml");
    const auto items = complete(*index, at(text, "entries: [\"0x7000:1\"", 0, 11));
    const CompletionItem* object = find(items, "0x7000");
    ASSERT_TRUE(object);
    EXPECT_EQ(object->detail, "Digital outputs");
    const CompletionItem* sub = find(items, "0x7000:3");
    ASSERT_TRUE(sub);
    EXPECT_EQ(sub->detail, "Output 3");
    EXPECT_EQ(sub->insert_text, "\"0x7000:3\"");
    EXPECT_EQ(sub->replace, test::token_range(text, "entries: [\"0x7000:1\"", "0x7000:1"));
}

TEST(YamlCompletion, TypeOffersBasicAndDeclaredTypes) {
    const std::string text = "devices:\n  - type: X\n    objects:\n      0x2000: { name: P, type: UI";
    const auto index = build_index(text, "x.yaml");
    const auto items = complete(*index, LineMap(text).position_of(text.size()));
    const CompletionItem* uint = find(items, "UINT");
    ASSERT_TRUE(uint);
    EXPECT_EQ(uint->detail, "UNSIGNED16, 16 bits");
    EXPECT_EQ(uint->replace, LineMap(text).range_of(text.size() - 2, text.size()));
    // After the value, another key: nothing to offer.
    const std::string later = "devices:\n  - type: X\n    objects:\n      0x2000: { name: P, type: UINT, access: r";
    EXPECT_TRUE(complete(*build_index(later, "x.yaml"), LineMap(later).position_of(later.size())).empty());
}

TEST(YamlCompletion, BlockSequenceUnderEntries) {
    const std::string text = esi::test::read_text(esi::test::source_dir() / "samples/digital-io-8.yaml");
    std::string edited = text;
    const std::string flow = "entries: [\"0x6000:1\", \"0x6000:2\", \"0x6000:3\", \"0x6000:4\", \"0x6000:5\", \"0x6000:6\", \"0x6000:7\", \"0x6000:8\"]";
    const std::size_t at_flow = edited.find(flow);
    ASSERT_NE(at_flow, std::string::npos);
    edited.replace(at_flow, flow.size(), "entries:\n          - \"0x6000:1\"\n          - 0x");
    const auto index = build_index(edited, "d.yaml");
    const std::size_t cursor = edited.find("- 0x") + 4;
    const auto items = complete(*index, LineMap(edited).position_of(cursor));
    EXPECT_TRUE(find(items, "0x6000"));
}

}  // namespace
}  // namespace esi::navigate
