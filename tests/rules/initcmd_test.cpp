// InitCmd rules beyond the fixtures: modules, one finding per fault, and the dictionary lookup.
#include <gtest/gtest.h>

#include <algorithm>

#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

std::size_t count(const esi::FileReport& report, std::string_view rule) {
    return static_cast<std::size_t>(
        std::count_if(report.diagnostics.begin(), report.diagnostics.end(), [&](const esi::Diagnostic& d) { return d.rule == rule; }));
}

esi::FileReport lint(const std::string& xml) { return esi::lint_bytes(xml, "test.xml", esi::EffectiveConfig{}); }

const std::string controlword_dictionary =
    "<Profile><Dictionary><DataTypes><DataType><Name>UINT</Name><BitSize>16</BitSize></DataType></DataTypes><Objects>"
    "<Object><Index>#x6040</Index><Name>Controlword</Name><Type>UINT</Type><BitSize>16</BitSize></Object>"
    "</Objects></Dictionary></Profile>";

std::string device_with(const std::string& profile, const std::string& init_cmds) {
    return "<EtherCATInfo><Vendor><Id>#x00000E4A</Id><Name>Example</Name></Vendor><Descriptions>"
           "<Groups><Group><Type>G</Type><Name>G</Name></Group></Groups><Devices>"
           "<Device Physics=\"YY\"><Type ProductCode=\"#x1\" RevisionNo=\"#x1\">D</Type><Name>D</Name><GroupType>G</GroupType>" +
           profile +
           "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>"
           "<Sm StartAddress=\"#x1080\" ControlByte=\"#x22\" DefaultSize=\"128\" Enable=\"1\">MBoxIn</Sm>"
           "<Mailbox DataLinkLayer=\"true\"><CoE>" +
           init_cmds + "</CoE></Mailbox></Device></Devices></Descriptions></EtherCATInfo>";
}

TEST(InitCmdRules, OddDataIsOneFindingNotAlsoALengthFault) {
    // The servo manuals' example: Controlword (16 bits) written with Data "0".
    const auto report = lint(device_with(controlword_dictionary,
                                         "<InitCmd><Transition>PS</Transition><Index>#x6040</Index><SubIndex>0</SubIndex>"
                                         "<Data>0</Data><Comment>control_word</Comment></InitCmd>"));
    EXPECT_EQ(count(report, "initcmd-data-hex"), 1u);
    EXPECT_EQ(count(report, "initcmd-data-length"), 0u);
}

TEST(InitCmdRules, DataLengthNamesTheTargetAndTheAbortCode) {
    const auto report = lint(device_with(controlword_dictionary,
                                         "<InitCmd><Transition>PS</Transition><Index>#x6040</Index><SubIndex>0</SubIndex>"
                                         "<Data>060000</Data></InitCmd>"));
    ASSERT_EQ(count(report, "initcmd-data-length"), 1u);
    const auto it = std::find_if(report.diagnostics.begin(), report.diagnostics.end(),
                                 [](const esi::Diagnostic& d) { return d.rule == "initcmd-data-length"; });
    EXPECT_NE(it->message.find("3 bytes"), std::string::npos) << it->message;
    EXPECT_NE(it->message.find("'Controlword' is UINT, 16 bits"), std::string::npos) << it->message;
    EXPECT_NE(it->message.find("0x06070012"), std::string::npos) << it->message;
}

TEST(InitCmdRules, WithoutADictionaryTargetsAreNotJudged) {
    const auto report = lint(device_with("", "<InitCmd><Transition>PS</Transition><Index>#x6061</Index><SubIndex>0</SubIndex>"
                                             "<Data>0300</Data></InitCmd>"));
    EXPECT_EQ(count(report, "initcmd-target-missing"), 0u);
    EXPECT_EQ(count(report, "initcmd-data-length"), 0u);
}

TEST(InitCmdRules, ModuleInitCmdsAreCheckedAgainstTheModulesOwnDictionary) {
    const std::string xml =
        "<EtherCATModule><Vendor><Id>#x00000E4A</Id><Name>Example</Name></Vendor><Modules><Module>"
        "<Type ModuleIdent=\"#x1\">AX1</Type><Name>Axis</Name>"
        "<Mailbox><CoE>"
        "<InitCmd><Transition>ip</Transition><Index>#x6040</Index><SubIndex>0</SubIndex><Data>0600</Data></InitCmd>"
        "<InitCmd><Transition>PS</Transition><Index>#x6041</Index><SubIndex>0</SubIndex><Data>0600</Data></InitCmd>"
        "</CoE></Mailbox>" +
        controlword_dictionary + "</Module></Modules></EtherCATModule>";
    const auto report = lint(xml);
    EXPECT_EQ(count(report, "initcmd-transition-unknown"), 1u);
    EXPECT_EQ(count(report, "initcmd-target-missing"), 1u);
    EXPECT_EQ(count(report, "mailbox-data-link-layer"), 0u);  // a module's Mailbox is no device mailbox
}

TEST(InitCmdRules, SoeInitCmdsGetTransitionChecksButNoDictionaryLookup) {
    std::string xml = device_with(controlword_dictionary, "");
    const std::string empty_coe = "<CoE></CoE>";
    xml.replace(xml.find(empty_coe), empty_coe.size(),
                "<SoE><InitCmd><Transition>SI</Transition><IDN>32</IDN><Data>0100</Data></InitCmd></SoE>");
    const auto report = lint(xml);
    EXPECT_EQ(count(report, "initcmd-transition-not-allowed"), 1u);
    EXPECT_EQ(count(report, "initcmd-target-missing"), 0u);
}

TEST(InitCmdRules, CorpusInitCmdsUseAllowedTransitionsAndValidData) {
    ESI_REQUIRE_CORPUS();
    // 615 InitCmds (565 SoE, 50 CoE) in the corpus, all at IP, PS or SO with even-length Data.
    std::size_t transition_faults = 0;
    std::size_t data_faults = 0;
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (entry.path().extension() != ".xml") continue;
        const auto report = esi::lint_bytes(esi::test::read_text(entry.path()), entry.path().string(), esi::EffectiveConfig{});
        transition_faults += count(report, "initcmd-transition-unknown") + count(report, "initcmd-transition-not-allowed") +
                             count(report, "initcmd-transition-missing");
        data_faults += count(report, "initcmd-data-hex") + count(report, "initcmd-data-length");
    }
    EXPECT_EQ(transition_faults, 0u);
    EXPECT_EQ(data_faults, 0u);
}

}  // namespace
