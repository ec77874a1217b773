#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "esi/model/object_layout.hpp"
#include "esi/xml/reader.hpp"
#include "support/test_support.hpp"

namespace {

// A Beckhoff-style dictionary: a record (0x1018), an array via an "Elements" item (0x1C13),
// and a plain variable (0x6000).
const char* dictionary_xml = R"(<EtherCATDict><Dictionary>
<DataTypes>
  <DataType><Name>DT1018</Name><BitSize>144</BitSize>
    <SubItem><SubIdx>0</SubIdx><Name>SubIndex 000</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs></SubItem>
    <SubItem><SubIdx>1</SubIdx><Name>Vendor ID</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>16</BitOffs></SubItem>
    <SubItem><SubIdx>2</SubIdx><Name>Product code</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>48</BitOffs></SubItem>
  </DataType>
  <DataType><Name>DT1C13ARR</Name><BaseType>UINT</BaseType><BitSize>32</BitSize><ArrayInfo><LBound>1</LBound><Elements>2</Elements></ArrayInfo></DataType>
  <DataType><Name>DT1C13</Name><BitSize>48</BitSize>
    <SubItem><SubIdx>0</SubIdx><Name>SubIndex 000</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs><Flags><Access>rw</Access></Flags></SubItem>
    <SubItem><Name>Elements</Name><Type>DT1C13ARR</Type><BitSize>32</BitSize><BitOffs>16</BitOffs><Flags><Access>rw</Access></Flags></SubItem>
  </DataType>
  <DataType><Name>LOOP_A</Name><BaseType>LOOP_B</BaseType><BitSize>8</BitSize></DataType>
  <DataType><Name>LOOP_B</Name><BaseType>LOOP_A</BaseType><BitSize>8</BitSize></DataType>
</DataTypes>
<Objects>
  <Object><Index>#x1018</Index><Name>Identity</Name><Type>DT1018</Type><BitSize>144</BitSize>
    <Info><SubItem><Name>SubIndex 000</Name><Info><DefaultData>02</DefaultData></Info></SubItem>
          <SubItem><Name>Vendor ID</Name><Info><DefaultData>02000000</DefaultData></Info></SubItem>
          <SubItem><Name>Product code</Name><Info><DefaultValue>#x4711</DefaultValue></Info></SubItem></Info>
    <Flags><Access>ro</Access></Flags></Object>
  <Object><Index>#x1C13</Index><Name>TxPDO assign</Name><Type>DT1C13</Type><BitSize>48</BitSize>
    <Info><SubItem><Name>SubIndex 000</Name><Info><DefaultData>02</DefaultData></Info></SubItem>
          <SubItem><Name>SubIndex 001</Name><Info><DefaultData>001A</DefaultData></Info></SubItem>
          <SubItem><Name>SubIndex 002</Name><Info><DefaultData>011A</DefaultData></Info></SubItem></Info></Object>
  <Object><Index>#x6000</Index><Name>Input</Name><Type>INT</Type><BitSize>16</BitSize><Flags><Access>ro</Access><PdoMapping>T</PdoMapping></Flags></Object>
</Objects></Dictionary></EtherCATDict>)";

}  // namespace

TEST(ObjectLayout, RecordEntriesWithValues) {
    const auto r = esi::read_esi(dictionary_xml, "d.xml");
    ASSERT_TRUE(r.document && r.document->dictionary);
    const auto& dict = *r.document->dictionary;
    const auto layout = esi::layout_of(&dict, *dict.find_object(0x1018));
    EXPECT_EQ(layout.code, esi::ObjectCode::record);
    ASSERT_EQ(layout.entries.size(), 3u);
    EXPECT_EQ(layout.entries[1].subindex, 1u);
    EXPECT_EQ(layout.entries[1].name, "Vendor ID");
    EXPECT_EQ(layout.entries[1].basic->esi_name, "UDINT");
    EXPECT_EQ(layout.entries[1].bit_offset, 16u);
    ASSERT_NE(layout.entries[2].info, nullptr);
    EXPECT_EQ(layout.entries[2].info->default_value->magnitude, 0x4711u);
    ASSERT_NE(layout.entries[1].flags, nullptr);
    EXPECT_EQ(layout.entries[1].flags->access, "ro");  // inherited from the object
}

TEST(ObjectLayout, ArrayThroughElementsItemExpandsFromLowerBound) {
    const auto r = esi::read_esi(dictionary_xml, "d.xml");
    const auto& dict = *r.document->dictionary;
    const auto layout = esi::layout_of(&dict, *dict.find_object(0x1C13));
    EXPECT_EQ(layout.code, esi::ObjectCode::array);
    ASSERT_EQ(layout.entries.size(), 3u);
    EXPECT_EQ(layout.entries[1].subindex, 1u);
    EXPECT_EQ(layout.entries[2].subindex, 2u);
    EXPECT_EQ(layout.entries[2].bit_size, 16u);
    EXPECT_EQ(layout.entries[2].bit_offset, 32u);
    EXPECT_EQ(layout.entries[2].basic->esi_name, "UINT");
    ASSERT_NE(layout.entries[2].info, nullptr);
    EXPECT_EQ(layout.entries[2].info->default_data->text, "011A");
}

TEST(ObjectLayout, VariableHasOneEntry) {
    const auto r = esi::read_esi(dictionary_xml, "d.xml");
    const auto& dict = *r.document->dictionary;
    const auto layout = esi::layout_of(&dict, *dict.find_object(0x6000));
    EXPECT_EQ(layout.code, esi::ObjectCode::var);
    ASSERT_EQ(layout.entries.size(), 1u);
    EXPECT_EQ(layout.entries[0].basic->esi_name, "INT");
    EXPECT_TRUE(layout.entries[0].basic->is_signed());
    EXPECT_EQ(layout.entries[0].flags->pdo_mapping, "T");
}

TEST(ObjectLayout, BaseTypeCycleIsDetectedNotLooped) {
    const auto r = esi::read_esi(dictionary_xml, "d.xml");
    const auto t = esi::resolve_type(&*r.document->dictionary, "LOOP_A");
    EXPECT_TRUE(t.cycle);
}

TEST(ObjectLayout, UnknownTypeIsNotKnown) {
    const auto t = esi::resolve_type(nullptr, "UINT16");
    EXPECT_FALSE(t.known);
    EXPECT_TRUE(esi::resolve_type(nullptr, "UINT").known);
}

namespace {

void expect_same_layout(const esi::ObjectLayout& a, const esi::ObjectLayout& b, const std::string& where) {
    EXPECT_EQ(a.code, b.code) << where;
    ASSERT_EQ(a.entries.size(), b.entries.size()) << where;
    for (std::size_t i = 0; i < a.entries.size(); ++i) {
        const esi::ObjectEntry& x = a.entries[i];
        const esi::ObjectEntry& y = b.entries[i];
        EXPECT_EQ(x.subindex, y.subindex) << where;
        EXPECT_EQ(x.name, y.name) << where;
        EXPECT_EQ(x.type, y.type) << where;
        EXPECT_EQ(x.basic, y.basic) << where;
        EXPECT_EQ(x.bit_size, y.bit_size) << where;
        EXPECT_EQ(x.bit_offset, y.bit_offset) << where;
        EXPECT_EQ(x.flags, y.flags) << where;
        EXPECT_EQ(x.info, y.info) << where;
        EXPECT_EQ(x.type_item, y.type_item) << where;
    }
}

// Every object of every Dictionary in a document, laid out both ways.
void expect_indexed_layouts_match(const esi::EsiDocument& document, const std::string& file) {
    std::vector<const esi::Dictionary*> dictionaries;
    if (document.dictionary) dictionaries.push_back(&*document.dictionary);
    for (const auto& info : document.infos) {
        for (const auto& device : info.devices)
            for (const auto& profile : device.profiles)
                if (profile.dictionary) dictionaries.push_back(&*profile.dictionary);
        for (const auto& module : info.modules)
            if (module.profile && module.profile->dictionary) dictionaries.push_back(&*module.profile->dictionary);
    }
    for (const esi::Dictionary* dictionary : dictionaries) {
        const esi::DataTypeIndex index(dictionary);
        for (const auto& object : dictionary->objects)
            expect_same_layout(esi::layout_of(dictionary, object), esi::layout_of(index, object),
                               file + " object " + std::to_string(object.index));
    }
}

}  // namespace

TEST(ObjectLayout, DataTypeIndexFindsTheFirstTypeOfAName) {
    const auto r = esi::read_esi(R"(<EtherCATDict><Dictionary><DataTypes>
        <DataType><Name>DT1</Name><BitSize>8</BitSize></DataType>
        <DataType><Name>DT1</Name><BitSize>16</BitSize></DataType>
        </DataTypes></Dictionary></EtherCATDict>)",
                                 "d.xml");
    const auto& dict = *r.document->dictionary;
    const esi::DataTypeIndex index(&dict);
    EXPECT_EQ(index.find("DT1"), &dict.data_types[0]);
    EXPECT_EQ(index.find("DT1"), dict.find_data_type("DT1"));
    EXPECT_EQ(index.find("DT2"), nullptr);
    EXPECT_EQ(esi::resolve_type(index, " DT1 ").bit_size, 8u);
    EXPECT_EQ(esi::DataTypeIndex(nullptr).find("DT1"), nullptr);
}

TEST(ObjectLayout, IndexedLookupGivesTheDictionaryLayouts) {
    const auto r = esi::read_esi(dictionary_xml, "d.xml");
    expect_indexed_layouts_match(*r.document, "d.xml");
    const esi::DataTypeIndex index(&*r.document->dictionary);
    EXPECT_TRUE(esi::resolve_type(index, "LOOP_A").cycle);
}

TEST(ObjectLayout, IndexedLookupGivesTheDictionaryLayoutsOnTheCorpus) {
    ESI_REQUIRE_CORPUS();
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (entry.path().extension() != ".xml") continue;
        const auto r = esi::read_esi_file(entry.path());
        if (r.document) expect_indexed_layouts_match(*r.document, entry.path().filename().string());
    }
}
