// The device facts of the seed manuals in the shipped profiles (samples/profiles/): mailbox
// protocols, the ESC's FMMUs and SyncManagers, who configures the PDOs, PDO names, STÖBER's
// parameter addressing and SYNC0 cycle, and the TR encoder profile. Each profile is read, sets
// what its manual states, and an ESI that breaks each fact once gets exactly the marked
// findings, while one built from the manuals' own statements gets none.

#include <gtest/gtest.h>

#include "rules/pdo_od_test_support.hpp"

namespace {

using esi::test::count_with_prefix;
using esi::test::finding_lines;
using esi::test::lint_text;
using esi::test::marked_lines;

const char* const device_rules[] = {"profile-mailbox-protocol", "profile-fmmu-count",      "profile-sm-count",
                                    "profile-pdo-assign",       "profile-pdo-config",      "profile-pdo-name",
                                    "profile-parameter-index",  "profile-sync0-cycle"};

esi::EffectiveConfig shipped(const std::string& name) {
    const auto path = esi::test::source_dir() / "samples" / "profiles" / name;
    const esi::ConfigResult loaded = esi::load_lint_config(path);
    for (const auto& d : loaded.diagnostics) ADD_FAILURE() << path << ":" << d.pos.line << ": " << d.message;
    if (!loaded.config) return {};
    return esi::effective_config(*loaded.config, path.parent_path() / "device.xml");
}

void expect_marked(const std::string& xml, const esi::EffectiveConfig& config, std::initializer_list<const char*> covered) {
    for (const char* rule : covered) EXPECT_FALSE(marked_lines(xml, rule).empty()) << "the test marks no line for " << rule;
    const auto report = lint_text(xml, config);
    for (const char* rule : device_rules) EXPECT_EQ(finding_lines(report, rule), marked_lines(xml, rule)) << "rule " << rule;
}

const std::string fmmus = "        <Fmmu>Outputs</Fmmu>\n        <Fmmu>Inputs</Fmmu>\n        <Fmmu>MBoxState</Fmmu>\n";

// --- item / Afag servo controllers --------------------------------------------------------------

TEST(ServoProfileFacts, CoeOnlyEsc20AndFixedPdoNames) {
    const esi::Limits l = shipped("servo-item-afag.yaml").limits;
    EXPECT_EQ(l.mailbox_protocols, (std::vector<std::string>{"CoE"}));
    EXPECT_EQ(l.max_fmmus, 4u);
    EXPECT_EQ(l.max_sms, 6u);
    EXPECT_EQ(l.rx_pdo_name, "Outputs");
    EXPECT_EQ(l.tx_pdo_name, "Inputs");
    EXPECT_FALSE(l.pdo_assign);  // the manuals' own CoE element sets PdoAssign="1" (§7)
    EXPECT_FALSE(l.parameter_index);
}

TEST(ServoProfileFacts, EveryFactIsEnforced) {
    const std::string xml = esi::test::one_device(
        fmmus +
        "        <Fmmu>Outputs</Fmmu>\n"
        "        <Fmmu>Inputs</Fmmu>  <!-- expect: profile-fmmu-count -->\n" +
        std::string(esi::test::standard_sms) +
        "        <Sm StartAddress=\"#x1800\" ControlByte=\"#x64\" Enable=\"0\">Outputs</Sm>\n"
        "        <Sm StartAddress=\"#x1900\" ControlByte=\"#x20\" Enable=\"0\">Inputs</Sm>\n"
        "        <Sm StartAddress=\"#x1A00\" ControlByte=\"#x20\" Enable=\"0\">Inputs</Sm>  <!-- expect: profile-sm-count -->\n"
        "        <RxPdo Fixed=\"1\" Sm=\"2\"><Index>#x1600</Index>\n"
        "          <Name>Output</Name>  <!-- expect: profile-pdo-name -->\n"
        "          <Entry><Index>#x6040</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>Controlword</Name><DataType>UINT</DataType></Entry>\n"
        "        </RxPdo>\n"
        "        <TxPdo Fixed=\"1\" Sm=\"3\"><Index>#x1A00</Index><Name>Inputs</Name>\n"
        "          <Entry><Index>#x6041</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>Statusword</Name><DataType>UINT</DataType></Entry>\n"
        "        </TxPdo>\n"
        "        <Mailbox>\n"
        "          <CoE DS402Channels=\"1\" PdoAssign=\"1\"/>\n"
        "          <FoE/>  <!-- expect: profile-mailbox-protocol -->\n"
        "        </Mailbox>\n",
        "#x264860D2");
    expect_marked(xml, shipped("servo-item-afag.yaml"), {"profile-mailbox-protocol", "profile-fmmu-count", "profile-sm-count", "profile-pdo-name"});
}

// --- STÖBER ECS 5000 inverters ------------------------------------------------------------------

TEST(StoeberProfileFacts, CoeAndVoeEsc20DevicePdoConfigurationParametersAndSync0) {
    const esi::Limits l = shipped("inverter-stoeber.yaml").limits;
    EXPECT_EQ(l.mailbox_protocols, (std::vector<std::string>{"CoE", "VoE"}));
    EXPECT_EQ(l.max_fmmus, 4u);
    EXPECT_EQ(l.max_sms, 6u);
    EXPECT_EQ(l.pdo_assign, false);
    EXPECT_EQ(l.pdo_config, false);
    ASSERT_TRUE(l.parameter_index);
    EXPECT_EQ(l.parameter_index->base, 0x2000u);
    EXPECT_EQ(l.parameter_index->group_size, 0x200u);
    EXPECT_EQ(l.parameter_index->first_group, 'A');
    EXPECT_EQ(l.parameter_index->last_group, 'Z');
    // The manual's own examples: A154.2 -> 0x209A, C01 -> 0x2401, E08 -> 0x2808; Z ends at 0x53FF.
    EXPECT_EQ(l.parameter_index->index_of('A', 154), 0x209Au);
    EXPECT_EQ(l.parameter_index->index_of('C', 1), 0x2401u);
    EXPECT_EQ(l.parameter_index->index_of('E', 8), 0x2808u);
    EXPECT_EQ(l.parameter_index->end(), 0x5400u);
    ASSERT_TRUE(l.sync0_cycle);
    EXPECT_EQ(l.sync0_cycle->min_ns, 1000000u);
    EXPECT_EQ(l.sync0_cycle->multiple_of_ns, 1000000u);
    EXPECT_TRUE(l.sync0_cycle->factors.empty());
    EXPECT_FALSE(l.rx_pdo_name);
}

const std::string stoeber_dictionary =
    "        <Profile><Dictionary>\n"
    "          <DataTypes><DataType><Name>USINT</Name><BitSize>8</BitSize></DataType><DataType><Name>INT</Name><BitSize>16</BitSize></DataType></DataTypes>\n"
    "          <Objects>\n";

TEST(StoeberProfileFacts, TheManualsOwnExamplesPass) {
    // Parameters named by coordinate at the formula's index, CoE + VoE without PdoAssign/PdoConfig,
    // and the DC modes of §11.5: SYNC0 = the PLC cycle (multiplier 1, 2) or an explicit 2 ms.
    const std::string xml = esi::test::one_device(
        stoeber_dictionary +
        "            <Object><Index>#x20B4</Index><Name>A180 Device Control Byte</Name><Type>USINT</Type><BitSize>8</BitSize></Object>\n"
        "            <Object><Index>#x209A</Index><Name>A154.2 example</Name><Type>USINT</Type><BitSize>8</BitSize></Object>\n"
        "            <Object><Index>#x26E6</Index><Name>D230 n-Soll Relativ</Name><Type>INT</Type><BitSize>16</BitSize></Object>\n"
        "          </Objects>\n"
        "        </Dictionary></Profile>\n" +
        fmmus + esi::test::standard_sms +
        "        <Mailbox><CoE SdoInfo=\"1\" PdoAssign=\"0\" PdoConfig=\"0\"/><VoE/></Mailbox>\n"
        "        <Dc>\n"
        "          <OpMode><Name>DC</Name><Desc>DC enabled (multiplier = 1)</Desc><AssignActivate>#x0300</AssignActivate>"
        "<CycleTimeSync0 Factor=\"1\">0</CycleTimeSync0></OpMode>\n"
        "          <OpMode><Name>DC x2</Name><Desc>DC enabled (multiplier = 2)</Desc><AssignActivate>#x0300</AssignActivate>"
        "<CycleTimeSync0 Factor=\"2\">0</CycleTimeSync0></OpMode>\n"
        "          <OpMode><Name>DC 2 ms</Name><AssignActivate>#x0300</AssignActivate><CycleTimeSync0>2000000</CycleTimeSync0></OpMode>\n"
        "        </Dc>\n");
    const auto report = lint_text(xml, shipped("inverter-stoeber.yaml"));
    EXPECT_EQ(count_with_prefix(report, "profile-"), 0u);
}

TEST(StoeberProfileFacts, EveryFactIsEnforced) {
    const std::string xml = esi::test::one_device(
        stoeber_dictionary +
        "            <Object>\n"
        "              <Index>#x20B5</Index>  <!-- expect: profile-parameter-index -->\n"
        "              <Name>A180 Device Control Byte</Name><Type>USINT</Type><BitSize>8</BitSize></Object>\n"
        "            <Object>\n"
        "              <Index>#x5400</Index>  <!-- expect: profile-parameter-index -->\n"
        "              <Name>Reserved</Name><Type>USINT</Type><BitSize>8</BitSize></Object>\n"
        "          </Objects>\n"
        "        </Dictionary></Profile>\n" +
        fmmus + esi::test::standard_sms +
        "        <Mailbox>\n"
        "          <EoE/>  <!-- expect: profile-mailbox-protocol -->\n"
        "          <CoE SdoInfo=\"1\" PdoAssign=\"1\" PdoConfig=\"1\">  <!-- expect: profile-pdo-assign --><!-- expect: profile-pdo-config -->\n"
        "            <InitCmd>  <!-- expect: profile-pdo-assign -->\n"
        "              <Transition>PS</Transition><Index>#x1C12</Index><SubIndex>0</SubIndex><Data>00</Data></InitCmd>\n"
        "          </CoE>\n"
        "          <VoE/>\n"
        "        </Mailbox>\n"
        "        <Dc>\n"
        "          <OpMode><Name>DC 500</Name><AssignActivate>#x0300</AssignActivate>\n"
        "            <CycleTimeSync0>500000</CycleTimeSync0>  <!-- expect: profile-sync0-cycle -->\n"
        "          </OpMode>\n"
        "          <OpMode><Name>DC 1.5</Name><AssignActivate>#x0300</AssignActivate>\n"
        "            <CycleTimeSync0>1500000</CycleTimeSync0>  <!-- expect: profile-sync0-cycle -->\n"
        "          </OpMode>\n"
        "        </Dc>\n");
    expect_marked(xml, shipped("inverter-stoeber.yaml"),
                  {"profile-mailbox-protocol", "profile-pdo-assign", "profile-pdo-config", "profile-parameter-index", "profile-sync0-cycle"});
}

// --- TR-Electronic linear encoders --------------------------------------------------------------

TEST(TrProfileFacts, LoadsWithTheManualsTransitionsAndCoeOnly) {
    const esi::Limits l = shipped("encoder-tr.yaml").limits;
    EXPECT_EQ(l.allowed_transitions, (std::vector<std::string>{"IP", "PI", "PS", "SP", "SO", "OS", "OP", "SI", "OI"}));
    EXPECT_EQ(l.mailbox_protocols, (std::vector<std::string>{"CoE"}));
    // What the manual does not limit stays open.
    EXPECT_FALSE(l.max_rx_pdos || l.max_tx_pdos || l.max_entries_per_pdo || l.max_init_cmd_bytes || l.max_mailbox_size);
}

TEST(TrProfileFacts, PositionValueInTheFirstTxPdoPassesAndFoeOrBootstrapDoNot) {
    const std::string body_start =
        "        <Fmmu>Inputs</Fmmu>\n        <Fmmu>MBoxState</Fmmu>\n" + std::string(esi::test::standard_sms) +
        "        <TxPdo Fixed=\"1\" Sm=\"3\"><Index>#x1A00</Index><Name>1st Transmit PDO</Name>\n"
        "          <Entry><Index>#x6004</Index><SubIndex>0</SubIndex><BitLen>32</BitLen><Name>Position value</Name><DataType>UDINT</DataType></Entry>\n"
        "        </TxPdo>\n";
    const std::string good = esi::test::one_device(body_start +
                                                   "        <Mailbox><CoE SdoInfo=\"1\" SegmentedSdo=\"1\" CompleteAccess=\"1\">\n"
                                                   "          <InitCmd><Transition>PS</Transition><Index>#x6003</Index><SubIndex>0</SubIndex>"
                                                   "<Data>0000000000000000</Data></InitCmd>\n"
                                                   "        </CoE></Mailbox>\n");
    EXPECT_EQ(count_with_prefix(lint_text(good, shipped("encoder-tr.yaml")), "profile-"), 0u);

    const std::string bad = esi::test::one_device(body_start +
                                                  "        <Mailbox>\n"
                                                  "          <CoE SdoInfo=\"1\">\n"
                                                  "            <InitCmd>\n"
                                                  "              <Transition>IB</Transition>  <!-- expect: profile-initcmd-transition -->\n"
                                                  "              <Index>#x6003</Index><SubIndex>0</SubIndex><Data>00000000</Data></InitCmd>\n"
                                                  "          </CoE>\n"
                                                  "          <FoE/>  <!-- expect: profile-mailbox-protocol -->\n"
                                                  "        </Mailbox>\n");
    const auto report = lint_text(bad, shipped("encoder-tr.yaml"));
    EXPECT_EQ(finding_lines(report, "profile-initcmd-transition"), marked_lines(bad, "profile-initcmd-transition"));
    EXPECT_EQ(finding_lines(report, "profile-mailbox-protocol"), marked_lines(bad, "profile-mailbox-protocol"));
    EXPECT_EQ(count_with_prefix(report, "profile-"), 2u);
}

TEST(ProfileFacts, TheNewRulesAreSilentWithoutLimits) {
    // Every fixture that breaks one of them is clean without its config.
    for (const char* rule : device_rules) {
        const auto bad = esi::test::read_text(esi::test::source_dir() / "tests" / "rules" / "fixtures" / rule / "bad.xml");
        EXPECT_EQ(count_with_prefix(lint_text(bad), "profile-"), 0u) << rule;
    }
}

}  // namespace
