// Device, its identity, FMMUs, SyncManagers and sync units.

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::device_file;
using esi::test::rewrite;

const std::string device_body = R"(
        <Type ProductCode="#x3f03052" RevisionNo="#x00100000" SerialNo="5" TcCfgModeSafeOp="1" CheckRevisionNo="EQ_OR_G">EL1008 </Type>
        <Name LcId="1033">EL1008 8Ch. Dig. Input</Name>
        <Comment>comment</Comment>
        <URL>https://example.com</URL>
        <Info><Electrical><EBusCurrent>90</EBusCurrent></Electrical></Info>
        <GroupType>IO</GroupType>
        <Fmmu OpOnly="0" Sm="3" Su="1">Inputs</Fmmu>
        <Fmmu>MBoxState</Fmmu>
        <Sm ControlByte="#x26" StartAddress="#x1000" DefaultSize="128" MinSize="34" MaxSize="1024" Enable="1" Watchdog="true">MBoxOut</Sm>
        <Sm StartAddress="4352" ControlByte="34" Enable="1" OneByteMode="0" Virtual="1" OpOnly="true" FixedAssignment="false">MBoxIn</Sm>
        <Sm StartAddress="#x1800" ControlByte="#x20" Enable="9"/>
        <Su SeparateSu="1" SeparateFrame="0" DependOnInputState="true" FrameRepeatSupport="false">su</Su>
        <ESC><Reg0400>#x09C2</Reg0400></ESC>
        <ImageData16x14>ff</ImageData16x14>)";

TEST(WriterDevice, WritesIdentityAsHexWithEightDigitsAndKeepsUnknownTypeAttributes) {
    const std::string out = rewrite(device_file(device_body, R"( Invisible="1" Physics="KK" Crc32="#x1234")"));
    EXPECT_TRUE(contains(out, R"(<Device Physics="KK" Invisible="true" Crc32="#x1234">)")) << out;
    EXPECT_TRUE(contains(out,
                         R"(<Type ProductCode="#x03F03052" RevisionNo="#x00100000" SerialNo="#x00000005" TcCfgModeSafeOp="true" CheckRevisionNo="EQ_OR_G">EL1008</Type>)"))
        << out;
}

TEST(WriterDevice, WritesChildrenInSchemaOrder) {
    const std::string out = rewrite(device_file(device_body));
    const char* order[] = {"<Type ", "<Name ", "<Comment>", "<URL>", "<Info>", "<GroupType>", "<Fmmu ", "<Sm ", "<Su ", "<ESC>",
                           "<ImageData16x14>"};
    std::size_t last = 0;
    for (const char* tag : order) {
        const std::size_t at = out.find(tag, last);
        ASSERT_NE(at, std::string::npos) << tag << " missing or out of order in\n" << out;
        last = at;
    }
}

TEST(WriterDevice, WritesSyncManagersWithAddressesInHexAndSizesInDecimal) {
    const std::string out = rewrite(device_file(device_body));
    EXPECT_TRUE(contains(
        out, R"(<Sm StartAddress="#x1000" ControlByte="#x26" DefaultSize="128" MinSize="34" MaxSize="1024" Enable="1" Watchdog="true">MBoxOut</Sm>)"))
        << out;
    EXPECT_TRUE(contains(
        out,
        R"(<Sm StartAddress="#x1100" ControlByte="#x22" Enable="1" OneByteMode="false" Virtual="true" OpOnly="true" FixedAssignment="false">MBoxIn</Sm>)"))
        << out;
    EXPECT_TRUE(contains(out, R"(<Sm StartAddress="#x1800" ControlByte="#x20" Enable="9"/>)")) << out;
}

TEST(WriterDevice, WritesFmmusAndSyncUnits) {
    const std::string out = rewrite(device_file(device_body));
    EXPECT_TRUE(contains(out, R"(<Fmmu Sm="3" Su="1" OpOnly="false">Inputs</Fmmu>)")) << out;
    EXPECT_TRUE(contains(out, R"(<Fmmu>MBoxState</Fmmu>)")) << out;
    EXPECT_TRUE(contains(out, R"(<Su SeparateSu="true" SeparateFrame="false" DependOnInputState="true" FrameRepeatSupport="false">su</Su>)"))
        << out;
}

TEST(WriterDevice, KeepsUnknownDeviceChildrenWhereTheyWere) {
    const std::string out = rewrite(device_file(device_body));
    EXPECT_TRUE(contains(out,
                         "        <URL>https://example.com</URL>\n"
                         "        <Info>\n"
                         "          <Electrical>\n"
                         "            <EBusCurrent>90</EBusCurrent>\n"
                         "          </Electrical>\n"
                         "        </Info>\n"
                         "        <GroupType>IO</GroupType>\n"))
        << out;
    EXPECT_TRUE(contains(out, "        <ESC>\n          <Reg0400>#x09C2</Reg0400>\n        </ESC>\n        <ImageData16x14>FF</ImageData16x14>\n"))
        << out;
}

TEST(WriterDevice, RoundTripLosesNothing) { EXPECT_EQ(esi::test::tree_differences(device_file(device_body)), ""); }

TEST(WriterDevice, PhysicsIsAlwaysWrittenBecauseTheSchemaRequiresIt) {
    const std::string out = rewrite(device_file("<Type>X</Type><Name>X</Name>", ""));
    EXPECT_TRUE(contains(out, R"(<Device Physics="">)")) << out;
}

TEST(WriterDevice, SeveralProfilesAndAllPdoListsKeepTheirOrder) {
    const std::string body = R"(<Type>X</Type><Name>X</Name><GroupType>IO</GroupType>
        <Profile><ProfileNo>5001</ProfileNo></Profile><Profile><ProfileNo>402</ProfileNo><AddInfo>2</AddInfo></Profile>
        <RxPdo><Index>#x1601</Index><Name>b</Name></RxPdo><RxPdo><Index>#x1600</Index><Name>a</Name></RxPdo>
        <TxPdo><Index>#x1A00</Index><Name>c</Name></TxPdo>)";
    const auto doc = esi::test::read_ok(rewrite(device_file(body)));
    const auto& d = doc.infos.at(0).devices.at(0);
    ASSERT_EQ(d.profiles.size(), 2u);
    EXPECT_EQ(d.profiles[1].profile_no, 402);
    EXPECT_EQ(d.profiles[1].add_info, 2);
    ASSERT_EQ(d.rx_pdos.size(), 2u);
    EXPECT_EQ(d.rx_pdos[0].index, 0x1601u);  // PDOs are not sorted: their order is the file's
    EXPECT_EQ(d.tx_pdos.at(0).index, 0x1A00u);
}

}  // namespace
