// The vendor constraint profiles shipped in samples/profiles/ enforce the limits of their
// manuals: a small ESI per device family that breaks each limit once gets exactly the marked
// profile-* findings, a compliant one (built from the manuals' own examples) gets none, and
// without a profile the profile-* rules stay silent.

#include <gtest/gtest.h>

#include "rules/pdo_od_test_support.hpp"

namespace {

using esi::test::count_with_prefix;
using esi::test::finding_lines;
using esi::test::lint_text;
using esi::test::marked_lines;

std::filesystem::path profile_path(const std::string& name) { return esi::test::source_dir() / "samples" / "profiles" / name; }

esi::EffectiveConfig profile_config(const std::filesystem::path& path) {
    const esi::ConfigResult loaded = esi::load_lint_config(path);
    for (const auto& d : loaded.diagnostics) ADD_FAILURE() << path << ":" << d.pos.line << ": " << d.message;
    if (!loaded.config) return {};
    return esi::effective_config(*loaded.config, path.parent_path() / "device.xml");
}

const char* const profile_rules[] = {"profile-max-pdos",           "profile-pdo-index-range", "profile-max-entries",
                                     "profile-bitlen",             "profile-fixed-sm",        "profile-initcmd-transition",
                                     "profile-initcmd-size",       "profile-mailbox-size",    "profile-absent-object"};

// `covered`: the rules the test text must exercise (so that a missing mark cannot pass silently).
void expect_marked_findings(const std::string& xml, const esi::EffectiveConfig& config, std::initializer_list<const char*> covered) {
    for (const char* rule : covered) EXPECT_FALSE(marked_lines(xml, rule).empty()) << "the test marks no line for " << rule;
    const auto report = lint_text(xml, config);
    for (const char* rule : profile_rules)
        EXPECT_EQ(finding_lines(report, rule), marked_lines(xml, rule)) << "rule " << rule;
}

// --- item / Afag servo controllers (servo manuals §6.1, §6.3, §6.7, Tabelle 5-15) --------------

// The RxPDO of §6.7.2 (Controlword, Mode_Of_Operation) and the InitCmd of §7 (with even-length
// Data), on the SMs the manuals fix.
const std::string servo_compliant = esi::test::one_device(
    "        <Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>\n"
    "        <Sm StartAddress=\"#x1080\" ControlByte=\"#x22\" DefaultSize=\"128\" Enable=\"1\">MBoxIn</Sm>\n"
    "        <Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm>\n"
    "        <Sm StartAddress=\"#x1400\" ControlByte=\"#x20\" Enable=\"1\">Inputs</Sm>\n"
    "        <RxPdo Fixed=\"1\" Sm=\"2\">\n"
    "          <Index>#x1600</Index>\n"
    "          <Name>Outputs</Name>\n"
    "          <Entry><Index>#x6040</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>Controlword</Name><DataType>UINT</DataType></Entry>\n"
    "          <Entry><Index>#x6060</Index><SubIndex>0</SubIndex><BitLen>8</BitLen><Name>Mode_Of_Operation</Name><DataType>USINT</DataType></Entry>\n"
    "        </RxPdo>\n"
    "        <TxPdo Fixed=\"1\" Sm=\"3\">\n"
    "          <Index>#x1A00</Index>\n"
    "          <Name>Inputs</Name>\n"
    "          <Entry><Index>#x6041</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>Statusword</Name><DataType>UINT</DataType></Entry>\n"
    "          <Entry><Index>#x6064</Index><SubIndex>0</SubIndex><BitLen>32</BitLen><Name>Position</Name><DataType>DINT</DataType></Entry>\n"
    "        </TxPdo>\n"
    "        <Mailbox>\n"
    "          <CoE DS402Channels=\"1\" PdoAssign=\"1\">\n"
    "            <InitCmd><Transition>PS</Transition><Index>#x6040</Index><SubIndex>0</SubIndex><Data>0000</Data><Comment>control_word</Comment></InitCmd>\n"
    "            <InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data><Comment>velocity mode</Comment></InitCmd>\n"
    "          </CoE>\n"
    "        </Mailbox>\n",
    "#x264860D2");

const std::string servo_violations = esi::test::one_device(
    "        <Profile><Dictionary><DataTypes/><Objects>\n"
    "          <Object><Index>#x1008</Index><Name>Device name</Name><Type>STRING(8)</Type><BitSize>64</BitSize></Object>  <!-- expect: profile-absent-object -->\n"
    "        </Objects></Dictionary></Profile>\n"
    "        <Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>\n"
    "        <Sm StartAddress=\"#x1080\" ControlByte=\"#x22\" DefaultSize=\"128\" Enable=\"1\">MBoxIn</Sm>\n"
    "        <Sm StartAddress=\"#x1100\" ControlByte=\"#x20\" Enable=\"1\">Inputs</Sm>  <!-- expect: profile-fixed-sm -->\n"
    "        <Sm StartAddress=\"#x1400\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm>  <!-- expect: profile-fixed-sm -->\n"
    "        <RxPdo Sm=\"3\"><Index>#x1600</Index><Name>Outputs</Name>\n"
    "          <Entry><Index>#x6040</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><DataType>UINT</DataType></Entry>\n"
    "          <Entry><Index>#x60FE</Index><SubIndex>1</SubIndex>\n"
    "            <BitLen>1</BitLen>  <!-- expect: profile-bitlen -->\n"
    "            <DataType>BOOL</DataType></Entry>\n"
    "          <Entry><Index>#x0</Index><BitLen>7</BitLen></Entry>\n"
    "        </RxPdo>\n"
    "        <RxPdo><Index>#x1601</Index><Name>Outputs</Name></RxPdo>\n"
    "        <RxPdo><Index>#x1602</Index><Name>Outputs</Name></RxPdo>\n"
    "        <RxPdo><Index>#x1603</Index><Name>Outputs</Name></RxPdo>\n"
    "        <RxPdo>  <!-- expect: profile-max-pdos -->\n"
    "          <Index>#x1604</Index>  <!-- expect: profile-pdo-index-range -->\n"
    "          <Name>Outputs</Name></RxPdo>\n"
    "        <TxPdo Sm=\"2\"><Index>#x1A00</Index><Name>Inputs</Name>\n"
    "          <Entry><Index>#x1008</Index><SubIndex>0</SubIndex><BitLen>64</BitLen><DataType>STRING(8)</DataType></Entry>  <!-- expect: profile-absent-object --><!-- expect: profile-bitlen -->\n"
    "        </TxPdo>\n"
    "        <Mailbox>\n"
    "          <CoE>\n"
    "            <InitCmd><Transition>PS</Transition><Index>#x6040</Index><SubIndex>0</SubIndex>\n"
    "              <Data>0000000000000000</Data>  <!-- expect: profile-initcmd-size -->\n"
    "            </InitCmd>\n"
    "            <InitCmd>\n"
    "              <Transition>IB</Transition>  <!-- expect: profile-initcmd-transition -->\n"
    "              <Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>\n"
    "          </CoE>\n"
    "        </Mailbox>\n",
    "#x264860D2");

TEST(ServoProfile, LoadsAndSetsTheManualsLimits) {
    const auto config = profile_config(profile_path("servo-item-afag.yaml"));
    const esi::Limits& l = config.limits;
    EXPECT_EQ(l.max_rx_pdos, 4u);
    EXPECT_EQ(l.max_tx_pdos, 4u);
    ASSERT_EQ(l.rx_pdo_ranges.size(), 1u);
    EXPECT_EQ(l.rx_pdo_ranges[0].first, 0x1600u);
    EXPECT_EQ(l.rx_pdo_ranges[0].last, 0x1603u);
    ASSERT_EQ(l.tx_pdo_ranges.size(), 1u);
    EXPECT_EQ(l.tx_pdo_ranges[0].last, 0x1A03u);
    EXPECT_EQ(l.allowed_bit_lens, (std::vector<std::uint32_t>{8, 16, 32}));
    EXPECT_EQ(l.fixed_sms.at(2), "Outputs");
    EXPECT_EQ(l.fixed_sms.at(3), "Inputs");
    EXPECT_EQ(l.max_init_cmd_bytes, 4u);
    EXPECT_EQ(l.absent_objects, (std::vector<std::uint32_t>{0x1008, 0x1009, 0x100A}));
    EXPECT_EQ(l.allowed_transitions.size(), 9u);
}

TEST(ServoProfile, TheManualsOwnExamplesPass) {
    const auto report = lint_text(servo_compliant, profile_config(profile_path("servo-item-afag.yaml")));
    EXPECT_EQ(count_with_prefix(report, "profile-"), 0u);
}

TEST(ServoProfile, EveryLimitIsEnforced) {
    expect_marked_findings(servo_violations, profile_config(profile_path("servo-item-afag.yaml")),
                           {"profile-max-pdos", "profile-pdo-index-range", "profile-bitlen", "profile-fixed-sm",
                            "profile-initcmd-transition", "profile-initcmd-size", "profile-absent-object"});
}

// --- STÖBER ECS 5000 inverters (STÖBER manual §5.2, §7.1, §7.1.1, §8.2, §10.1) ------------------

// The preset process data of the "Schnellsollwert" application (§7.1.2): A180, D230, C230 out;
// E200, D200, E100, E02 in.
const std::string stoeber_compliant = esi::test::one_device(
    "        <Sm StartAddress=\"#x1800\" ControlByte=\"#x26\" DefaultSize=\"256\" Enable=\"1\">MBoxOut</Sm>\n"
    "        <Sm StartAddress=\"#x1900\" ControlByte=\"#x22\" DefaultSize=\"256\" Enable=\"1\">MBoxIn</Sm>\n"
    "        <Sm StartAddress=\"#x1000\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm>\n"
    "        <Sm StartAddress=\"#x1100\" ControlByte=\"#x20\" Enable=\"1\">Inputs</Sm>\n"
    "        <RxPdo Sm=\"2\"><Index>#x1600</Index><Name>1. PDO (rx)</Name>\n"
    "          <Entry><Index>#x20B4</Index><SubIndex>0</SubIndex><BitLen>8</BitLen><Name>A180</Name><DataType>USINT</DataType></Entry>\n"
    "          <Entry><Index>#x26E6</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>D230</Name><DataType>INT</DataType></Entry>\n"
    "          <Entry><Index>#x24E6</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>C230</Name><DataType>INT</DataType></Entry>\n"
    "        </RxPdo>\n"
    "        <RxPdo><Index>#x1601</Index><Name>2. PDO (rx)</Name></RxPdo>\n"
    "        <TxPdo Sm=\"3\"><Index>#x1A00</Index><Name>1. PDO (tx)</Name>\n"
    "          <Entry><Index>#x28C8</Index><SubIndex>0</SubIndex><BitLen>8</BitLen><Name>E200</Name><DataType>USINT</DataType></Entry>\n"
    "          <Entry><Index>#x26C8</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>D200</Name><DataType>INT</DataType></Entry>\n"
    "          <Entry><Index>#x2864</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>E100</Name><DataType>INT</DataType></Entry>\n"
    "          <Entry><Index>#x2802</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><Name>E02</Name><DataType>INT</DataType></Entry>\n"
    "        </TxPdo>\n"
    "        <Mailbox><CoE SdoInfo=\"1\"/><VoE/></Mailbox>\n");

const std::string stoeber_violations = esi::test::one_device(
    "        <Sm StartAddress=\"#x1800\" ControlByte=\"#x26\" DefaultSize=\"256\" Enable=\"1\">MBoxOut</Sm>\n"
    "        <Sm StartAddress=\"#x1900\" ControlByte=\"#x22\" DefaultSize=\"256\" Enable=\"1\">MBoxIn</Sm>\n"
    "        <Sm StartAddress=\"#x1000\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm>\n"
    "        <RxPdo Sm=\"2\">  <!-- expect: profile-max-entries -->\n"
    "          <Index>#x1600</Index><Name>1. PDO (rx)</Name>\n"
    "          <Entry><Index>#x20B4</Index><SubIndex>0</SubIndex><BitLen>8</BitLen><DataType>USINT</DataType></Entry>\n"
    "          <Entry><Index>#x0</Index><BitLen>8</BitLen></Entry>\n"
    "          <Entry><Index>#x26E6</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><DataType>INT</DataType></Entry>\n"
    "          <Entry><Index>#x24E6</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><DataType>INT</DataType></Entry>\n"
    "          <Entry><Index>#x2000</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><DataType>INT</DataType></Entry>\n"
    "          <Entry><Index>#x2001</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><DataType>INT</DataType></Entry>\n"
    "          <Entry><Index>#x2002</Index><SubIndex>0</SubIndex><BitLen>16</BitLen><DataType>INT</DataType></Entry>\n"
    "        </RxPdo>\n"
    "        <TxPdo><Index>#x1A00</Index><Name>1</Name></TxPdo>\n"
    "        <TxPdo><Index>#x1A01</Index><Name>2</Name></TxPdo>\n"
    "        <TxPdo><Index>#x1A02</Index><Name>3</Name></TxPdo>\n"
    "        <TxPdo><Index>#x1A03</Index><Name>4</Name></TxPdo>\n"
    "        <TxPdo>  <!-- expect: profile-max-pdos -->\n"
    "          <Index>#x1A04</Index>  <!-- expect: profile-pdo-index-range -->\n"
    "          <Name>5</Name></TxPdo>\n"
    "        <Mailbox><CoE>\n"
    "          <InitCmd>\n"
    "            <Transition>BI</Transition>  <!-- expect: profile-initcmd-transition -->\n"
    "            <Index>#x2000</Index><Data>0000</Data></InitCmd>\n"
    "        </CoE></Mailbox>\n");

TEST(StoeberProfile, TheManualsPresetProcessDataPass) {
    const auto report = lint_text(stoeber_compliant, profile_config(profile_path("inverter-stoeber.yaml")));
    EXPECT_EQ(count_with_prefix(report, "profile-"), 0u);
}

TEST(StoeberProfile, EveryLimitIsEnforced) {
    // The device lacks SM3 (Inputs): profile-fixed-sm reports it at the device.
    std::string xml = stoeber_violations;
    const auto device = xml.find("      <Device Physics=\"YY\">");
    xml.insert(xml.find('\n', device), "  <!-- expect: profile-fixed-sm -->");
    expect_marked_findings(xml, profile_config(profile_path("inverter-stoeber.yaml")),
                           {"profile-max-pdos", "profile-pdo-index-range", "profile-max-entries", "profile-fixed-sm",
                            "profile-initcmd-transition"});
}

TEST(Profiles, ProfileRulesAreSilentWithoutLimits) {
    for (const auto* xml : {&servo_violations, &stoeber_violations})
        EXPECT_EQ(count_with_prefix(lint_text(*xml), "profile-"), 0u);
}

TEST(Profiles, OverridesScopeAProfileToItsProductCodes) {
    // The servo's limits applied through an override for its product code: a device with another
    // product code in the same file is not held to them.
    esi::test::TempDir dir;
    esi::test::write_text(dir / ".esi-lint.yaml",
                          "overrides:\n"
                          "  - product_codes: [0x264860d2]\n"
                          "    limits: { max_pdos: { rx: 4, tx: 4 }, bitlen: [8, 16, 32] }\n");
    const auto loaded = esi::load_lint_config(dir / ".esi-lint.yaml");
    ASSERT_TRUE(loaded.config);
    const auto config = esi::effective_config(*loaded.config, dir / "device.xml");
    EXPECT_EQ(finding_lines(lint_text(servo_violations, config), "profile-max-pdos").size(), 1u);
    std::string other = servo_violations;
    other.replace(other.find("#x264860D2"), 10, "#x00000001");
    EXPECT_EQ(count_with_prefix(lint_text(other, config), "profile-"), 0u);
}

TEST(Profiles, ExtendingAShippedProfileWorksFromAnotherDirectory) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / ".esi-lint.yaml", "extends: [" + profile_path("inverter-stoeber.yaml").string() + "]\n"
                                                  "rules: { profile-fixed-sm: off }\n");
    const auto loaded = esi::load_lint_config(dir / ".esi-lint.yaml");
    ASSERT_TRUE(loaded.config);
    const auto report = lint_text(stoeber_violations, esi::effective_config(*loaded.config, dir / "device.xml"));
    EXPECT_EQ(finding_lines(report, "profile-max-entries"), marked_lines(stoeber_violations, "profile-max-entries"));
    EXPECT_TRUE(finding_lines(report, "profile-fixed-sm").empty());
}

}  // namespace
