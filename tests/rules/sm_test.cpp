// SyncManager, FMMU and mailbox rules beyond the fixtures: how roles are told apart without text,
// and that one fault gives one finding.
#include <gtest/gtest.h>

#include <algorithm>

#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

std::size_t count(const esi::FileReport& report, std::string_view rule) {
    return static_cast<std::size_t>(
        std::count_if(report.diagnostics.begin(), report.diagnostics.end(), [&](const esi::Diagnostic& d) { return d.rule == rule; }));
}

esi::FileReport lint(const std::string& device_body) {
    const std::string xml =
        "<EtherCATInfo><Vendor><Id>#x00000E4A</Id><Name>Example</Name></Vendor><Descriptions>"
        "<Groups><Group><Type>G</Type><Name>G</Name></Group></Groups><Devices>"
        "<Device Physics=\"YY\"><Type ProductCode=\"#x1\" RevisionNo=\"#x1\">D</Type><Name>D</Name><GroupType>G</GroupType>" +
        device_body + "</Device></Devices></Descriptions></EtherCATInfo>";
    return esi::lint_bytes(xml, "test.xml", esi::EffectiveConfig{});
}

esi::FileReport lint_corpus(const std::string& name) {
    const auto file = esi::test::corpus_esi_dir() / name;
    return esi::lint_bytes(esi::test::read_text(file), file.string(), esi::EffectiveConfig{});
}

const std::string rx_pdo_on_sm0 =
    "<RxPdo Fixed=\"1\" Sm=\"0\"><Index>#x1600</Index><Name>Out</Name>"
    "<Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>8</BitLen><DataType>USINT</DataType></Entry></RxPdo>";

TEST(SmRules, MailboxInBufferedModeIsOneFindingNotAnOverlapToo) {
    const auto report = lint(
        "<Sm StartAddress=\"#x1000\" ControlByte=\"#x24\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>"
        "<Sm StartAddress=\"#x1080\" ControlByte=\"#x22\" DefaultSize=\"128\" Enable=\"1\">MBoxIn</Sm>"
        "<Mailbox DataLinkLayer=\"true\"><CoE/></Mailbox>");
    EXPECT_EQ(count(report, "sm-mailbox-mode"), 1u);
    EXPECT_EQ(count(report, "sm-overlap"), 0u);
}

TEST(SmRules, TextlessSingleBufferSmWithPdosIsProcessData) {
    // IgH-written descriptions leave the text out; #x46 is single-buffer write, here carrying a PDO.
    const auto report = lint("<Sm StartAddress=\"#x0F00\" ControlByte=\"#x46\" DefaultSize=\"0\" Enable=\"1\"/>" + rx_pdo_on_sm0);
    EXPECT_EQ(count(report, "sm-mailbox-size"), 0u);
    EXPECT_EQ(count(report, "sm-size-zero"), 0u);  // sized by its PDO
    ASSERT_EQ(count(report, "fmmu-missing"), 1u);
    const auto it = std::find_if(report.diagnostics.begin(), report.diagnostics.end(),
                                 [](const esi::Diagnostic& d) { return d.rule == "fmmu-missing"; });
    EXPECT_NE(it->message.find("no Outputs Fmmu"), std::string::npos) << it->message;
}

TEST(SmRules, TextlessSingleBufferSmWithoutPdosIsAMailbox) {
    const auto report = lint("<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"8\" Enable=\"1\"/>"
                             "<Sm StartAddress=\"#x1080\" ControlByte=\"#x22\" DefaultSize=\"128\" Enable=\"1\"/>");
    EXPECT_EQ(count(report, "sm-mailbox-size"), 1u);
}

TEST(SmRules, ProcessDataSmIsSizedByItsDefaultPdosForOverlap) {
    // DefaultSize 128 is the room the firmware reserves; the master sizes SM0 from its 1-byte PDO.
    const std::string sms =
        "<Fmmu>Outputs</Fmmu><Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"128\" Enable=\"1\">Outputs</Sm>"
        "<Fmmu>Inputs</Fmmu><Sm StartAddress=\"#x1180\" ControlByte=\"#x20\" DefaultSize=\"1\" Enable=\"1\">Inputs</Sm>";
    EXPECT_EQ(count(lint(sms + rx_pdo_on_sm0), "sm-overlap"), 0u);
    // Without a default PDO the 128 bytes count, three times: #x1100..#x127F covers #x1180.
    EXPECT_EQ(count(lint(sms), "sm-overlap"), 1u);
}

TEST(SmRules, ControlByteReservedAndDirectionAreSeparateFaults) {
    // #x33: reserved mode 11 and the read direction on a mailbox-out SM.
    const auto report = lint("<Sm StartAddress=\"#x1000\" ControlByte=\"#x33\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>");
    EXPECT_EQ(count(report, "sm-control-byte-reserved"), 1u);
    EXPECT_EQ(count(report, "sm-direction-mismatch"), 1u);
    EXPECT_EQ(count(report, "sm-mailbox-mode"), 0u);  // mode 11 is not buffered mode
}

TEST(SmRules, DigitalIoRegisterSmsOfBeckhoffTerminalsDoNotOverlap) {
    ESI_REQUIRE_CORPUS();
    // EL2809 and friends put 1-byte buffered SMs on 0x0F00, 0x0F01 (digital output register).
    EXPECT_EQ(count(lint_corpus("Beckhoff__EL2xxx__dls-ethercat.xml"), "sm-overlap"), 0u);
    EXPECT_EQ(count(lint_corpus("Beckhoff__EK18xx__dls-ethercat.xml"), "sm-overlap"), 0u);
}

TEST(SmRules, EnabledEmptyOutputsOfEl66xxAreFound) {
    ESI_REQUIRE_CORPUS();
    // ethercrab-rs/ethercrab #354 names EL6614 among the devices with an enabled SM of length 0.
    EXPECT_GT(count(lint_corpus("Beckhoff__EL66xx__dls-ethercat.xml"), "sm-size-zero"), 0u);
}

TEST(SmRules, CleanSampleStaysClean) {
    const auto file = esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml";
    const auto report = esi::lint_bytes(esi::test::read_text(file), file.string(), esi::EffectiveConfig{});
    for (const auto& d : report.diagnostics) ADD_FAILURE() << d.pos.line << ": " << d.rule << ": " << d.message;
}

}  // namespace
