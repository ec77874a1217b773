// Mailbox (every protocol, CoE flags, InitCmds), Dc op modes and Eeprom.

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::device_file;
using esi::test::rewrite;

const std::string mailbox_body = R"(<Type>X</Type><Name>X</Name><GroupType>IO</GroupType>
        <Mailbox DataLinkLayer="1" RealTimeMode="0">
          <AoE AdsRouter="1" GenerateOwnNetId="0" InitializeOwnNetId="true">
            <InitCmd><Transition>PS</Transition><Data>0102</Data><Comment>aoe</Comment></InitCmd>
          </AoE>
          <EoE IP="1" MAC="1" TimeStamp="0">
            <InitCmd><Transition>IP</Transition><Type>2</Type><Data>ab</Data></InitCmd>
          </EoE>
          <CoE SdoInfo="1" PdoAssign="false" PdoConfig="0" PdoUpload="1" CompleteAccess="0" EdsFile="x.eds" DS402Channels="2"
               SegmentedSdo="1" DiagHistory="1" SdoUploadWithMaxLength="0" TimeDistribution="1">
            <Object><Index>#x1000</Index><SubIndex>0</SubIndex><Data>00</Data></Object>
            <InitCmd Fixed="1" CompleteAccess="true" OverwrittenByModule="0">
              <Transition>PS</Transition>
              <Transition>SO</Transition>
              <Index DependOnSlot="1">24672</Index>
              <SubIndex>#x0</SubIndex>
              <Data AdaptAutomatically="1">08</Data>
              <Comment>Modes of operation</Comment>
            </InitCmd>
            <InitCmd><Transition>PS</Transition><Index>#x1C12</Index><SubIndex>0</SubIndex><Data/></InitCmd>
          </CoE>
          <FoE/>
          <SoE ChannelCount="2" DriveFollowsBit3Support="1">
            <InitCmd Chn="1"><Transition>PS</Transition><IDN>32</IDN><Data>0300</Data></InitCmd>
            <DiagFile>diag.xml</DiagFile>
          </SoE>
          <VoE><Anything a="1">x</Anything></VoE>
          <VendorSpecific><Mine/></VendorSpecific>
        </Mailbox>)";

TEST(WriterMailbox, WritesProtocolsInSchemaOrderWithTheirFlags) {
    const std::string out = rewrite(device_file(mailbox_body));
    const char* order[] = {"<Mailbox DataLinkLayer=\"true\" RealTimeMode=\"false\">",
                           "<AoE AdsRouter=\"true\" GenerateOwnNetId=\"false\" InitializeOwnNetId=\"true\">",
                           "<EoE IP=\"true\" MAC=\"true\" TimeStamp=\"false\">",
                           "<CoE SdoInfo=\"true\" PdoAssign=\"false\" PdoConfig=\"false\" PdoUpload=\"true\" CompleteAccess=\"false\" "
                           "EdsFile=\"x.eds\" DS402Channels=\"2\" SegmentedSdo=\"true\" DiagHistory=\"true\" SdoUploadWithMaxLength=\"false\" "
                           "TimeDistribution=\"true\">",
                           "<FoE/>",
                           "<SoE ChannelCount=\"2\" DriveFollowsBit3Support=\"true\">",
                           "<VoE>",
                           "<VendorSpecific>"};
    std::size_t last = 0;
    for (const char* tag : order) {
        const std::size_t at = out.find(tag, last);
        ASSERT_NE(at, std::string::npos) << tag << " missing or out of order in\n" << out;
        last = at;
    }
}

TEST(WriterMailbox, WritesCoeInitCmdsWithIndexInHexAndDataInUpperCase) {
    const std::string out = rewrite(device_file(mailbox_body));
    EXPECT_TRUE(contains(out,
                         "            <InitCmd Fixed=\"true\" CompleteAccess=\"true\" OverwrittenByModule=\"false\">\n"
                         "              <Transition>PS</Transition>\n"
                         "              <Transition>SO</Transition>\n"
                         "              <Index DependOnSlot=\"true\">#x6060</Index>\n"
                         "              <SubIndex>0</SubIndex>\n"
                         "              <Data AdaptAutomatically=\"true\">08</Data>\n"
                         "              <Comment>Modes of operation</Comment>\n"
                         "            </InitCmd>\n"))
        << out;
    EXPECT_TRUE(contains(out, "<Index>#x1C12</Index>\n              <SubIndex>0</SubIndex>\n              <Data/>\n")) << out;
}

TEST(WriterMailbox, WritesProtocolSpecificInitCmdFields) {
    const std::string out = rewrite(device_file(mailbox_body));
    EXPECT_TRUE(contains(out, "<InitCmd>\n              <Transition>IP</Transition>\n              <Type>2</Type>\n              <Data>AB</Data>\n"))
        << out;
    EXPECT_TRUE(contains(out, "<InitCmd Chn=\"1\">\n              <Transition>PS</Transition>\n              <IDN>32</IDN>\n")) << out;
    EXPECT_TRUE(contains(out, "<Data>0102</Data>\n              <Comment>aoe</Comment>")) << out;
}

TEST(WriterMailbox, KeepsUnknownProtocolContentInPlace) {
    const std::string out = rewrite(device_file(mailbox_body));
    EXPECT_TRUE(contains(out, "            <Object>\n              <Index>#x1000</Index>")) << out;  // CoE/Object before InitCmd
    EXPECT_LT(out.find("<Object>"), out.find("<InitCmd Fixed"));
    EXPECT_TRUE(contains(out, "            </InitCmd>\n            <DiagFile>diag.xml</DiagFile>\n          </SoE>")) << out;
    EXPECT_TRUE(contains(out, "<VoE>\n            <Anything a=\"1\">x</Anything>\n          </VoE>")) << out;
    EXPECT_EQ(esi::test::tree_differences(device_file(mailbox_body)), "");
}

TEST(WriterMailbox, EmptyDataStaysPresentAndMissingDataStaysAbsent) {
    const auto doc = esi::test::read_ok(rewrite(device_file(mailbox_body)));
    const auto& coe = *doc.infos.at(0).devices.at(0).mailbox->coe;
    ASSERT_EQ(coe.init_cmds.size(), 2u);
    EXPECT_TRUE(coe.init_cmds[1].has_data);
    EXPECT_EQ(coe.init_cmds[1].data.text, "");
    esi::EsiDocument edited = doc;
    edited.infos[0].devices[0].mailbox->coe->init_cmds[1].has_data = false;
    EXPECT_FALSE(contains(esi::write_esi(edited), "<Data/>"));
}

const std::string dc_body = R"(<Type>X</Type><Name>X</Name><GroupType>IO</GroupType>
        <Dc UnknownFRMW="1" Unknown64Bit="0" ExternalRefClock="true" PotentialReferenceClock="1" TimeLoopControlOnly="false">
          <OpMode>
            <Name>DcSync</Name>
            <Desc>DC-Synchron</Desc>
            <AssignActivate>#x300</AssignActivate>
            <CycleTimeSync0 Factor="1">0</CycleTimeSync0>
            <ShiftTimeSync0 Input="0" OutputDelayTime="10" InputDelayTime="20">-1000</ShiftTimeSync0>
            <CycleTimeSync1 Factor="-2">0</CycleTimeSync1>
            <ShiftTimeSync1 Factor="1">4000000000</ShiftTimeSync1>
            <Sm No="2"><Pdo>#x1600</Pdo></Sm>
            <VendorSpecific><x/></VendorSpecific>
          </OpMode>
          <OpMode><Name>FreeRun</Name><AssignActivate>0</AssignActivate></OpMode>
          <OpMode><Name>Broken</Name></OpMode>
        </Dc>)";

TEST(WriterDc, WritesOpModesWithAssignActivateInHexAndTimesInDecimal) {
    const std::string out = rewrite(device_file(dc_body));
    EXPECT_TRUE(contains(out,
                         "        <Dc UnknownFRMW=\"true\" Unknown64Bit=\"false\" ExternalRefClock=\"true\" PotentialReferenceClock=\"true\" "
                         "TimeLoopControlOnly=\"false\">\n"
                         "          <OpMode>\n"
                         "            <Name>DcSync</Name>\n"
                         "            <Desc>DC-Synchron</Desc>\n"
                         "            <AssignActivate>#x0300</AssignActivate>\n"
                         "            <CycleTimeSync0 Factor=\"1\">0</CycleTimeSync0>\n"
                         "            <ShiftTimeSync0 Input=\"false\" OutputDelayTime=\"10\" InputDelayTime=\"20\">-1000</ShiftTimeSync0>\n"
                         "            <CycleTimeSync1 Factor=\"-2\">0</CycleTimeSync1>\n"
                         "            <ShiftTimeSync1 Factor=\"1\">4000000000</ShiftTimeSync1>\n"
                         "            <Sm No=\"2\">\n"
                         "              <Pdo>#x1600</Pdo>\n"
                         "            </Sm>\n"
                         "            <VendorSpecific>\n"
                         "              <x/>\n"
                         "            </VendorSpecific>\n"
                         "          </OpMode>\n"))
        << out;
}

TEST(WriterDc, AssignActivateZeroIsKeptAndAMissingOneStaysMissing) {
    const std::string out = rewrite(device_file(dc_body));
    EXPECT_TRUE(contains(out, "<Name>FreeRun</Name>\n            <AssignActivate>#x0000</AssignActivate>\n")) << out;
    EXPECT_TRUE(contains(out, "<OpMode>\n            <Name>Broken</Name>\n          </OpMode>")) << out;
    EXPECT_EQ(esi::test::tree_differences(device_file(dc_body)), "");
}

TEST(WriterDc, WritesAssignActivateOfAHandBuiltModelEvenWithoutItsFlag) {
    esi::EsiDocument doc = esi::test::read_ok(device_file(dc_body));
    auto& mode = doc.infos.at(0).devices.at(0).dc->op_modes.at(2);
    mode.assign_activate = 0x700;  // has_assign_activate left false, as a generator might
    EXPECT_TRUE(contains(esi::write_esi(doc), "<Name>Broken</Name>\n            <AssignActivate>#x0700</AssignActivate>"));
}

const std::string eeprom_body = R"(<Type>X</Type><Name>X</Name><GroupType>IO</GroupType>
        <Eeprom AssignToPdi="1">
          <ByteSize>2048</ByteSize>
          <ConfigData>080e00cc
                      0000</ConfigData>
          <BootStrap>0010800080108000</BootStrap>
          <Category PreserveOnlineData="0"><CatNo>1</CatNo><Data>0a0b</Data></Category>
          <Category><CatNo>2</CatNo><DataString> text </DataString></Category>
          <Category><CatNo>3</CatNo><DataUINT>#x10</DataUINT></Category>
          <Category><CatNo>4</CatNo><DataUDINT>70000</DataUDINT></Category>
          <VendorSpecific><Y/></VendorSpecific>
        </Eeprom>)";

TEST(WriterEeprom, WritesStructuredEepromWithUpperCaseHexAndDecimalSizes) {
    const std::string out = rewrite(device_file(eeprom_body));
    EXPECT_TRUE(contains(out,
                         "        <Eeprom AssignToPdi=\"true\">\n"
                         "          <ByteSize>2048</ByteSize>\n"
                         "          <ConfigData>080E00CC0000</ConfigData>\n"
                         "          <BootStrap>0010800080108000</BootStrap>\n"
                         "          <Category PreserveOnlineData=\"false\">\n"
                         "            <CatNo>1</CatNo>\n"
                         "            <Data>0A0B</Data>\n"
                         "          </Category>\n"
                         "          <Category>\n"
                         "            <CatNo>2</CatNo>\n"
                         "            <DataString> text </DataString>\n"
                         "          </Category>\n"
                         "          <Category>\n"
                         "            <CatNo>3</CatNo>\n"
                         "            <DataUINT>16</DataUINT>\n"
                         "          </Category>\n"))
        << out;
    EXPECT_TRUE(contains(out, "<DataUDINT>70000</DataUDINT>")) << out;
    EXPECT_EQ(esi::test::tree_differences(device_file(eeprom_body)), "");
}

TEST(WriterEeprom, WritesARawImage) {
    const std::string out = rewrite(device_file("<Type>X</Type><Name>X</Name><GroupType>IO</GroupType><Eeprom><Data>00ff</Data></Eeprom>"));
    EXPECT_TRUE(contains(out, "<Eeprom>\n          <Data>00FF</Data>\n        </Eeprom>")) << out;
}

TEST(WriterEeprom, BrokenHexBinaryStaysVisiblyBroken) {
    // An odd digit count or a non-hex character is the lint rules' business; the writer keeps it.
    const std::string out = rewrite(device_file("<Type>X</Type><Name>X</Name><GroupType>IO</GroupType><Eeprom><Data>0fz</Data></Eeprom>"));
    EXPECT_TRUE(contains(out, "<Data>0Fz</Data>")) << out;
}

}  // namespace
