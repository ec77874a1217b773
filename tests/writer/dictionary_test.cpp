// Profile and the object dictionary: data types (records, arrays, enums), objects with info,
// sub-item info and flags.

#include "esi/model/object_layout.hpp"
#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::device_file;
using esi::test::rewrite;

const std::string dictionary_body = R"(<Type>X</Type><Name>X</Name><GroupType>IO</GroupType>
        <Profile Channel="1">
          <ProfileNo>402</ProfileNo>
          <AddInfo>0</AddInfo>
          <ChannelCount>1</ChannelCount>
          <Dictionary>
            <DataTypes>
              <DataType><Name>UINT</Name><BitSize>16</BitSize></DataType>
              <DataType><Name>DINT</Name><BitSize>32</BitSize></DataType>
              <DataType><Name>USINT</Name><BitSize>8</BitSize></DataType>
              <DataType>
                <Name>DT1018</Name>
                <BitSize>144</BitSize>
                <SubItem><SubIdx>0</SubIdx><Name>SubIndex 000</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs>
                  <Flags><Access>ro</Access></Flags></SubItem>
                <SubItem><SubIdx>1</SubIdx><Name>Vendor ID</Name><DisplayName LcId="1031">Hersteller</DisplayName><Type>UDINT</Type>
                  <Comment>c</Comment><BitSize>32</BitSize><BitOffs>16</BitOffs><DefaultValue>#x2</DefaultValue>
                  <Flags><Access ReadRestrictions="PreOP">ro</Access><Category>m</Category><PdoMapping>T</PdoMapping></Flags></SubItem>
              </DataType>
              <DataType><Name>UDINT</Name><BitSize>32</BitSize></DataType>
              <DataType><Index>#x800</Index><Name>ARRAY [0..3] OF DINT</Name><BaseType>DINT</BaseType><BitSize>128</BitSize>
                <ArrayInfo><LBound>0</LBound><Elements>4</Elements></ArrayInfo></DataType>
              <DataType><Name>DT0800EN03</Name><BitSize>3</BitSize>
                <EnumInfo><Text LcId="1033">off</Text><Enum>0</Enum></EnumInfo>
                <EnumInfo><Text>on</Text><Text LcId="1031">an</Text><Enum>#x1</Enum><Comment>c</Comment></EnumInfo>
                <EnumInfo><Text>minus</Text><Enum>-1</Enum></EnumInfo>
              </DataType>
            </DataTypes>
            <Objects>
              <Object>
                <Index>#x1018</Index>
                <Name>Identity</Name>
                <Type>DT1018</Type>
                <BitSize>144</BitSize>
                <Info>
                  <SubItem><Name>SubIndex 000</Name><Info><DefaultData>01</DefaultData></Info></SubItem>
                  <SubItem><Name>Vendor ID</Name><Info><MinValue>0</MinValue><MaxValue>#xffffffff</MaxValue><DefaultValue>2</DefaultValue></Info></SubItem>
                </Info>
                <Flags><Access>ro</Access><Category>m</Category></Flags>
              </Object>
              <Object>
                <Index DependOnSlot="1" OverwrittenByModule="0">#x6064</Index>
                <Name LcId="1033">Position actual value</Name>
                <Comment>c</Comment>
                <Type>DINT</Type>
                <BitSize>32</BitSize>
                <Info><MinValue>-2147483648</MinValue><MaxValue>2147483647</MaxValue><DefaultValue>-5</DefaultValue><Unit>#xFD040000</Unit></Info>
                <Flags><Access WriteRestrictions="PreOP_SafeOP">rw</Access><PdoMapping>T</PdoMapping><SafetyMapping>si</SafetyMapping>
                  <Attribute>#x63120001</Attribute><Transition>PS</Transition><SdoAccess>CompleteAccess</SdoAccess><Backup>1</Backup><Setting>0</Setting></Flags>
                <Properties><Property><Name>p</Name><Value>v</Value></Property></Properties>
              </Object>
              <Object><Index>#x1008</Index><Name>Device name</Name><Type>STRING(4)</Type><BitSize>32</BitSize><Info><DefaultString>ab&lt;c</DefaultString></Info></Object>
              <Object><Index>#x3000</Index><Name>Big</Name><Type>ULINT</Type><BitSize>64</BitSize>
                <Info><DefaultValue>18446744073709551615</DefaultValue><DisplayName>big</DisplayName></Info></Object>
              <Object><Index>#x3001</Index><Name>Raw</Name><Type>OCTET_STRING</Type><BitSize>16</BitSize>
                <Info><MinData>0000</MinData><MaxData>ffff</MaxData><DefaultData>beef</DefaultData></Info></Object>
            </Objects>
          </Dictionary>
          <VendorSpecific><Z/></VendorSpecific>
        </Profile>)";

TEST(WriterDictionary, WritesProfileInSchemaOrder) {
    const std::string out = rewrite(device_file(dictionary_body));
    EXPECT_TRUE(contains(out,
                         "        <Profile Channel=\"1\">\n"
                         "          <ProfileNo>402</ProfileNo>\n"
                         "          <AddInfo>0</AddInfo>\n"
                         "          <ChannelCount>1</ChannelCount>\n"
                         "          <Dictionary>\n"
                         "            <DataTypes>\n"))
        << out;
    EXPECT_TRUE(contains(out, "          </Dictionary>\n          <VendorSpecific>\n            <Z/>\n          </VendorSpecific>\n        </Profile>"))
        << out;
}

TEST(WriterDictionary, WritesRecordTypesWithSubItemsInSchemaOrder) {
    const std::string out = rewrite(device_file(dictionary_body));
    EXPECT_TRUE(contains(out,
                         "                <SubItem>\n"
                         "                  <SubIdx>1</SubIdx>\n"
                         "                  <Name>Vendor ID</Name>\n"
                         "                  <DisplayName LcId=\"1031\">Hersteller</DisplayName>\n"
                         "                  <Type>UDINT</Type>\n"
                         "                  <Comment>c</Comment>\n"
                         "                  <BitSize>32</BitSize>\n"
                         "                  <BitOffs>16</BitOffs>\n"
                         "                  <DefaultValue>2</DefaultValue>\n"
                         "                  <Flags>\n"
                         "                    <Access ReadRestrictions=\"PreOP\">ro</Access>\n"
                         "                    <Category>m</Category>\n"
                         "                    <PdoMapping>T</PdoMapping>\n"
                         "                  </Flags>\n"
                         "                </SubItem>\n"))
        << out;
}

TEST(WriterDictionary, WritesArrayAndEnumTypes) {
    const std::string out = rewrite(device_file(dictionary_body));
    EXPECT_TRUE(contains(out,
                         "                <Index>#x0800</Index>\n"
                         "                <Name>ARRAY [0..3] OF DINT</Name>\n"
                         "                <BaseType>DINT</BaseType>\n"
                         "                <BitSize>128</BitSize>\n"
                         "                <ArrayInfo>\n"
                         "                  <LBound>0</LBound>\n"
                         "                  <Elements>4</Elements>\n"
                         "                </ArrayInfo>\n"))
        << out;
    EXPECT_TRUE(contains(out,
                         "                <EnumInfo>\n"
                         "                  <Text>on</Text>\n"
                         "                  <Text LcId=\"1031\">an</Text>\n"
                         "                  <Enum>1</Enum>\n"
                         "                  <Comment>c</Comment>\n"
                         "                </EnumInfo>\n"))
        << out;
    EXPECT_TRUE(contains(out, "<Enum>-1</Enum>")) << out;
}

TEST(WriterDictionary, WritesObjectsWithInfoAndFlags) {
    const std::string out = rewrite(device_file(dictionary_body));
    EXPECT_TRUE(contains(out,
                         "              <Object>\n"
                         "                <Index DependOnSlot=\"true\" OverwrittenByModule=\"false\">#x6064</Index>\n"
                         "                <Name LcId=\"1033\">Position actual value</Name>\n"
                         "                <Comment>c</Comment>\n"
                         "                <Type>DINT</Type>\n"
                         "                <BitSize>32</BitSize>\n"
                         "                <Info>\n"
                         "                  <MinValue>-2147483648</MinValue>\n"
                         "                  <MaxValue>2147483647</MaxValue>\n"
                         "                  <DefaultValue>-5</DefaultValue>\n"
                         "                  <Unit>#xFD040000</Unit>\n"
                         "                </Info>\n"
                         "                <Flags>\n"
                         "                  <Access WriteRestrictions=\"PreOP_SafeOP\">rw</Access>\n"
                         "                  <PdoMapping>T</PdoMapping>\n"
                         "                  <SafetyMapping>si</SafetyMapping>\n"
                         "                  <Attribute>#x63120001</Attribute>\n"
                         "                  <Transition>PS</Transition>\n"
                         "                  <SdoAccess>CompleteAccess</SdoAccess>\n"
                         "                  <Backup>1</Backup>\n"
                         "                  <Setting>0</Setting>\n"
                         "                </Flags>\n"
                         "                <Properties>\n"))
        << out;
}

TEST(WriterDictionary, WritesSubItemInfoAndHexDataAndStrings) {
    const std::string out = rewrite(device_file(dictionary_body));
    EXPECT_TRUE(contains(out,
                         "                  <SubItem>\n"
                         "                    <Name>Vendor ID</Name>\n"
                         "                    <Info>\n"
                         "                      <MinValue>0</MinValue>\n"
                         "                      <MaxValue>4294967295</MaxValue>\n"
                         "                      <DefaultValue>2</DefaultValue>\n"
                         "                    </Info>\n"
                         "                  </SubItem>\n"))
        << out;
    EXPECT_TRUE(contains(out, "<DefaultString>ab&lt;c</DefaultString>")) << out;
    EXPECT_TRUE(contains(out, "<DefaultValue>18446744073709551615</DefaultValue>\n                  <DisplayName>big</DisplayName>")) << out;
    EXPECT_TRUE(contains(out, "<MinData>0000</MinData>\n                  <MaxData>FFFF</MaxData>\n                  <DefaultData>BEEF</DefaultData>"))
        << out;
}

TEST(WriterDictionary, RoundTripKeepsTheObjectLayout) {
    const auto original = esi::test::read_ok(device_file(dictionary_body));
    const auto rewritten = esi::test::read_ok(esi::write_esi(original));
    const auto* a = original.infos.at(0).devices.at(0).dictionary();
    const auto* b = rewritten.infos.at(0).devices.at(0).dictionary();
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->objects.size(), b->objects.size());
    for (std::size_t i = 0; i < a->objects.size(); ++i) {
        const auto la = esi::layout_of(a, a->objects[i]);
        const auto lb = esi::layout_of(b, b->objects[i]);
        EXPECT_EQ(la.code, lb.code);
        ASSERT_EQ(la.entries.size(), lb.entries.size());
        for (std::size_t k = 0; k < la.entries.size(); ++k) {
            EXPECT_EQ(la.entries[k].bit_size, lb.entries[k].bit_size);
            EXPECT_EQ(la.entries[k].bit_offset, lb.entries[k].bit_offset);
            EXPECT_EQ(la.entries[k].type, lb.entries[k].type);
        }
    }
    EXPECT_EQ(b->objects[1].index_depend_on_slot, true);
    EXPECT_EQ(b->objects[3].info->default_value, (esi::Number{UINT64_MAX, false}));
    EXPECT_EQ(b->data_types[6].enums[2].value, esi::Number::from_signed(-1));
    EXPECT_EQ(esi::test::tree_differences(device_file(dictionary_body)), "");
}

TEST(WriterDictionary, ObjectsElementIsWrittenEvenWhenEmpty) {
    const std::string out = rewrite(device_file("<Type>X</Type><Name>X</Name><GroupType>IO</GroupType><Profile><Dictionary/></Profile>"));
    EXPECT_TRUE(contains(out, "<Dictionary>\n            <Objects/>\n          </Dictionary>")) << out;
}

TEST(WriterDictionary, WritesADictionaryFileReference) {
    const std::string out = rewrite(device_file("<Type>X</Type><Name>X</Name><GroupType>IO</GroupType><Profile><DictionaryFile>d.xml</DictionaryFile></Profile>"));
    EXPECT_TRUE(contains(out, "<Profile>\n          <DictionaryFile>d.xml</DictionaryFile>\n        </Profile>")) << out;
}

}  // namespace
