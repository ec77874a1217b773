#include <gtest/gtest.h>

#include "esi/model/object_layout.hpp"
#include "esi/xml/reader.hpp"

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
