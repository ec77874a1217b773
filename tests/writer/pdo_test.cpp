// RxPdo / TxPdo and their entries.

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::device_file;
using esi::test::rewrite;

const std::string pdo_body = R"(<Type>X</Type><Name>X</Name><GroupType>IO</GroupType>
        <RxPdo Sm="2" Fixed="1" Mandatory="true" Virtual="0" Su="1" PdoOrder="3" OSFac="2" OSMin="1" OSMax="4" OSIndexInc="16"
               OverwrittenByModule="false" SRA_Parameter="true" SafetyPdoType="FSoESlave" SafetyConnNumber="1" Vendor="x">
          <Index DependOnSlot="1" DependOnSlotGroup="0">5632</Index>
          <Name LcId="1033">Outputs</Name>
          <Name LcId="1031">Ausgaben</Name>
          <Exclude DependOnSlot="true">#x1601</Exclude>
          <Exclude>#x1602</Exclude>
          <Entry Fixed="1" SafetyConnNumber="2">
            <Index DependOnSlotGroup="1">#x7000</Index>
            <SubIndex>#x11</SubIndex>
            <BitLen>1</BitLen>
            <Name>Output 1</Name>
            <Comment>first</Comment>
            <DataType DScale="0-10">BOOL</DataType>
          </Entry>
          <Entry><Index>0</Index><BitLen>7</BitLen></Entry>
          <Entry><Index>#x6040</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><DataType>UINT</DataType></Entry>
          <ExcludedSm>3</ExcludedSm>
          <ExcludedSm>4</ExcludedSm>
        </RxPdo>
        <TxPdo Sm="3"><Index>#x1a00</Index><Name>Inputs</Name><Entry><Index>#x6041</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>Statusword</Name><DataType>UINT</DataType></Entry></TxPdo>)";

TEST(WriterPdo, WritesPdoAttributesInAFixedOrder) {
    const std::string out = rewrite(device_file(pdo_body));
    EXPECT_TRUE(contains(out, R"(<RxPdo Fixed="true" Mandatory="true" Virtual="false" Sm="2" Su="1" PdoOrder="3" OSFac="2" OSMin="1" OSMax="4" )"
                              R"(OSIndexInc="16" OverwrittenByModule="false" SRA_Parameter="true" SafetyPdoType="FSoESlave" SafetyConnNumber="1" Vendor="x">)"))
        << out;
}

TEST(WriterPdo, WritesIndicesAsFourHexDigitsWithTheirSlotFlags) {
    const std::string out = rewrite(device_file(pdo_body));
    EXPECT_TRUE(contains(out, R"(<Index DependOnSlot="true" DependOnSlotGroup="false">#x1600</Index>)")) << out;
    EXPECT_TRUE(contains(out, R"(<Exclude DependOnSlot="true">#x1601</Exclude>)")) << out;
    EXPECT_TRUE(contains(out, R"(<Exclude>#x1602</Exclude>)")) << out;
    EXPECT_TRUE(contains(out, R"(<Index>#x1A00</Index>)")) << out;
}

TEST(WriterPdo, WritesEntriesWithSubIndexAndBitLenInDecimal) {
    const std::string out = rewrite(device_file(pdo_body));
    EXPECT_TRUE(contains(out,
                         "          <Entry Fixed=\"true\" SafetyConnNumber=\"2\">\n"
                         "            <Index DependOnSlotGroup=\"true\">#x7000</Index>\n"
                         "            <SubIndex>17</SubIndex>\n"
                         "            <BitLen>1</BitLen>\n"
                         "            <Name>Output 1</Name>\n"
                         "            <Comment>first</Comment>\n"
                         "            <DataType DScale=\"0-10\">BOOL</DataType>\n"
                         "          </Entry>\n"))
        << out;
}

TEST(WriterPdo, WritesPaddingEntriesWithIndexZeroAndNoSubIndex) {
    const std::string out = rewrite(device_file(pdo_body));
    EXPECT_TRUE(contains(out, "          <Entry>\n            <Index>#x0000</Index>\n            <BitLen>7</BitLen>\n          </Entry>\n"))
        << out;
}

TEST(WriterPdo, WritesExcludedSmsLast) {
    const std::string out = rewrite(device_file(pdo_body));
    EXPECT_TRUE(contains(out, "          </Entry>\n          <ExcludedSm>3</ExcludedSm>\n          <ExcludedSm>4</ExcludedSm>\n        </RxPdo>\n"))
        << out;
}

TEST(WriterPdo, KeepsEntryOrderAndEveryField) {
    const auto doc = esi::test::read_ok(rewrite(device_file(pdo_body)));
    const auto& pdo = doc.infos.at(0).devices.at(0).rx_pdos.at(0);
    ASSERT_EQ(pdo.entries.size(), 3u);
    EXPECT_EQ(pdo.entries[0].index, 0x7000u);
    EXPECT_EQ(pdo.entries[0].subindex, 0x11u);
    EXPECT_EQ(pdo.entries[0].index_depend_on_slot_group, true);
    EXPECT_EQ(pdo.entries[0].data_type_dscale, "0-10");
    EXPECT_TRUE(pdo.entries[1].is_padding());
    EXPECT_FALSE(pdo.entries[1].subindex.has_value());
    EXPECT_EQ(pdo.entries[2].subindex, 0u);  // an explicit SubIndex 0 stays explicit
    EXPECT_EQ(pdo.bit_size(), 24u);
    EXPECT_EQ(pdo.excluded_sms, (std::vector<std::uint32_t>{3, 4}));
    EXPECT_EQ(pdo.safety_pdo_type, "FSoESlave");
    EXPECT_EQ(esi::test::tree_differences(device_file(pdo_body)), "");
}

TEST(WriterPdo, WritesSwapDataAsTheModelHoldsIt) {
    esi::EsiDocument doc = esi::test::read_ok(device_file(pdo_body));
    auto& entry = doc.infos.at(0).devices.at(0).rx_pdos.at(0).entries.at(2);
    entry.data_type_swap_data = "Swap_HB_LB";
    EXPECT_TRUE(contains(esi::write_esi(doc), R"(<DataType SwapData="Swap_HB_LB">UINT</DataType>)"));
}

}  // namespace
