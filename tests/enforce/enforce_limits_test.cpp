// esi::enforce_limits: the limits a generated device is held to. A YAML source that breaks its own
// `limits:` (or those of a --config profile) gets the profile-* findings at the line:column of
// the offending PDO, entry, InitCmd, object or op mode in the YAML; how the profile's limits and
// the source's combine; how the profile's rule settings grade them; and that devices without
// limits are not checked at all.

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "enforce/enforce_test_support.hpp"
#include "esi/check/registry.hpp"

namespace {

using esi::test::enforce::check;
using esi::test::enforce::describe;
using esi::test::enforce::findings;
using esi::test::enforce::line_of;
using esi::test::enforce::fifth_rx_pdo;
using esi::test::enforce::stoeber_with_a180_at_20b5;
using esi::test::enforce::stoeber_with_a_fifth_rx_pdo;
using esi::test::enforce::stoeber_with_an_init_cmd_at_ib;
using esi::test::enforce::stoeber_with_seven_entries;
using esi::test::enforce::Where;
using esi::test::read_text;
using esi::test::TempDir;
using esi::test::write_text;

// ---- the four cases of issue 11, on the STÖBER sample and its declared limits --------------------

TEST(EnforceLimits, TheSamplesDeclaredLimitsHold) {
    for (const char* name : {"servo-item-c-series.yaml", "inverter-stoeber-mds5000.yaml", "encoder-tr-linear.yaml",
                             "digital-io-8.yaml", "modular-coupler.yaml"}) {
        const auto path = esi::test::source_dir() / "samples" / name;
        const esi::Diagnostics found = check(read_text(path), path.string());
        EXPECT_TRUE(found.empty()) << name << ":\n" << describe(found);
    }
}

TEST(EnforceLimits, AFifthRxPdoIsLocatedAtThatPdo) {
    const std::string text = stoeber_with_a_fifth_rx_pdo();
    const auto found = check(text);
    const std::uint32_t line = line_of(text, fifth_rx_pdo);
    EXPECT_EQ(findings(found, "profile-max-pdos"), (std::set<Where>{{line, 9}})) << describe(found);
    EXPECT_EQ(findings(found, "profile-pdo-index-range"), (std::set<Where>{{line, 18}})) << describe(found);
    EXPECT_TRUE(found.has_errors());
}

TEST(EnforceLimits, SevenEntriesAreLocatedAtTheirPdo) {
    const std::string text = stoeber_with_seven_entries();
    const auto found = check(text);
    EXPECT_EQ(findings(found, "profile-max-entries"), (std::set<Where>{{line_of(text, "{ index: 0x1600,"), 9}})) << describe(found);
    for (const auto& d : found) EXPECT_TRUE(d.rule.starts_with("profile-")) << d.rule;
}

TEST(EnforceLimits, AnInitCmdAtAnUnsupportedTransitionIsLocatedAtTheTransition) {
    const std::string text = stoeber_with_an_init_cmd_at_ib();
    const auto found = check(text);
    EXPECT_EQ(findings(found, "profile-initcmd-transition"), (std::set<Where>{{line_of(text, "transition: IB"), 23}}))
        << describe(found);
}

TEST(EnforceLimits, AWrongStoeberParameterIndexIsLocatedAtTheObject) {
    const std::string text = stoeber_with_a180_at_20b5();
    const auto found = check(text);
    EXPECT_EQ(findings(found, "profile-parameter-index"), (std::set<Where>{{line_of(text, "0x20B5:"), 7}})) << describe(found);
    ASSERT_EQ(found.size(), 1u) << describe(found);
    EXPECT_NE(found.items()[0].message.find("A180 is at #x20B4"), std::string::npos) << found.items()[0].message;
}

// ---- every profile rule points into the YAML ---------------------------------------------------

// One device that breaks every limit once; each rule's finding must sit on the line of what it is
// about. Derived SyncManagers and FMMUs sit where what they come from is declared: the mailbox's
// (SM0, SM1, the MBoxState FMMU) at the mailbox, the process data's at the device.
const std::string every_limit_broken = R"(vendor: { id: 0xE4, name: Example }
devices:
  - type: EX
    name: EX
    product_code: 0x10
    revision: 1
    group: G
    mailbox:
      size: 128
      coe: { sdo_info: false, pdo_assign: true, pdo_config: true }
      foe: true
    objects:
      0x1008: { name: Device name, type: STRING(8), access: ro }
      0x20B5: { name: A180 Control, type: USINT, access: rw, pdo: rx }
      0x6040: { name: Controlword, type: UINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, name: Outputs, entries: [0x6040, 0x20B5] }
      - { index: 0x1601, name: Other, assigned: false, entries: [] }
    init:
      - { transition: SO, object: 0x6040, value: 0 }
    dc:
      - { name: DC, assign_activate: 0x0300, cycle_time_sync0: 500000 }
    limits:
      max_pdos: { rx: 1 }
      pdo_index_ranges: { rx: ["0x1600-0x1600"] }
      max_entries_per_pdo: 1
      bitlen: [16]
      fixed_sm: { 2: Inputs }
      transitions: [PS]
      max_init_cmd_bytes: 1
      max_mailbox_size: 64
      absent_objects: [0x1008]
      mailbox_protocols: [CoE]
      max_fmmus: 1
      max_sms: 2
      pdo_assign: false
      pdo_config: false
      pdo_names: { rx: Outputs }
      parameter_index: { base: 0x2000, group_size: 0x200 }
      sync0_cycle: { min_ns: 1000000 }
)";

TEST(EnforceLimits, EveryProfileRuleReportsAtTheYamlLineOfWhatItIsAbout) {
    const auto found = check(every_limit_broken);
    const std::map<std::string, std::string> line_text = {
        {"profile-max-pdos", "index: 0x1601"},
        {"profile-pdo-index-range", "index: 0x1601"},
        {"profile-max-entries", "index: 0x1600"},
        {"profile-bitlen", "index: 0x1600"},
        {"profile-fixed-sm", "- type: EX"},
        {"profile-initcmd-transition", "transition: SO"},
        {"profile-initcmd-size", "transition: SO"},
        {"profile-mailbox-size", "size: 128"},
        {"profile-absent-object", "0x1008:"},
        {"profile-mailbox-protocol", "foe: true"},
        {"profile-fmmu-count", "size: 128"},
        {"profile-sm-count", "- type: EX"},
        {"profile-pdo-assign", "coe: {"},
        {"profile-pdo-config", "coe: {"},
        {"profile-pdo-name", "index: 0x1601"},
        {"profile-parameter-index", "0x20B5:"},
        {"profile-sync0-cycle", "cycle_time_sync0"},
    };
    // The table covers the whole profile area of the catalogue.
    std::set<std::string> catalogue;
    for (const auto& rule : esi::all_rules())
        if (rule.id.starts_with("profile-") && rule.check) catalogue.insert(std::string(rule.id));
    std::set<std::string> covered;
    for (const auto& [rule, text] : line_text) covered.insert(rule);
    EXPECT_EQ(covered, catalogue);

    for (const auto& [rule, text] : line_text) {
        SCOPED_TRACE(rule);
        const auto at = findings(found, rule);
        ASSERT_FALSE(at.empty()) << describe(found);
        for (const auto& [line, column] : at) {
            EXPECT_EQ(line, line_of(every_limit_broken, text)) << describe(found);
            EXPECT_GT(column, 0u);
        }
    }
    for (const auto& d : found) EXPECT_EQ(d.path, "device.yaml");
}

// ---- the profile and the source together -------------------------------------------------------

// A small source whose device has three RxPDOs, 8-bit entries and no limits of its own.
const std::string three_rx_pdos = R"(vendor: { id: 0xE4, name: Example }
devices:
  - type: EX
    name: EX
    product_code: 0x10
    revision: 1
    group: G
    mailbox: { size: 128, coe: { sdo_info: false } }
    objects:
      0x7000: { name: Out, type: USINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, entries: [0x7000] }
      - { index: 0x1601, assigned: false, entries: [] }
      - { index: 0x1602, assigned: false, entries: [] }
)";

TEST(EnforceLimits, WithoutLimitsNothingIsChecked) {
    EXPECT_TRUE(check(three_rx_pdos).empty());
    // An ESI file has no limits of its own.
    const auto esi = esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml";
    EXPECT_TRUE(check(read_text(esi), esi.string()).empty());
}

TEST(EnforceLimits, TheConfigsLimitsApplyToASourceWithoutLimits) {
    TempDir dir;
    write_text(dir / "profile.yaml", "limits: { max_pdos: { rx: 2 }, bitlen: [16] }\n");
    const auto found = check(three_rx_pdos, "device.yaml", dir / "profile.yaml");
    EXPECT_EQ(findings(found, "profile-max-pdos"), (std::set<Where>{{line_of(three_rx_pdos, "index: 0x1602"), 9}}));
    EXPECT_EQ(findings(found, "profile-bitlen"), (std::set<Where>{{line_of(three_rx_pdos, "index: 0x1600"), 36}}));
}

TEST(EnforceLimits, TheSourcesLimitsReplaceTheConfigsFieldByField) {
    TempDir dir;
    write_text(dir / "profile.yaml", "limits: { max_pdos: { rx: 2 }, bitlen: [16] }\n");
    // The source allows three RxPDOs; the profile's bitlen still holds.
    std::string text = three_rx_pdos + "    limits: { max_pdos: { rx: 3 } }\n";
    const auto found = check(text, "device.yaml", dir / "profile.yaml");
    EXPECT_TRUE(findings(found, "profile-max-pdos").empty()) << describe(found);
    EXPECT_EQ(findings(found, "profile-bitlen").size(), 1u) << describe(found);
}

TEST(EnforceLimits, TheConfigGradesTheProfileRules) {
    TempDir dir;
    write_text(dir / "warn.yaml", "rules: { profile-max-pdos: warning, profile-bitlen: off }\n"
                                  "limits: { max_pdos: { rx: 2 }, bitlen: [16] }\n");
    const auto found = check(three_rx_pdos, "device.yaml", dir / "warn.yaml");
    ASSERT_EQ(found.size(), 1u) << describe(found);
    EXPECT_EQ(found.items()[0].rule, "profile-max-pdos");
    EXPECT_EQ(found.items()[0].severity, esi::Severity::warning);
    EXPECT_FALSE(found.has_errors());
}

TEST(EnforceLimits, OnlyProfileRulesRunEvenWhenTheConfigRaisesOthers) {
    // esi-gen enforces limits; esi-lint's other rules stay esi-lint's, whatever the config says.
    TempDir dir;
    write_text(dir / "strict.yaml", "rules: { pdo-entry-alignment: error, od-default-range: error }\n"
                                    "limits: { max_pdos: { rx: 8 } }\n");
    EXPECT_TRUE(check(three_rx_pdos, "device.yaml", dir / "strict.yaml").empty());
}

TEST(EnforceLimits, OverridesByFileAndProductCodeResolveForTheSource) {
    TempDir dir;
    write_text(dir / "profile.yaml", "overrides:\n"
                                     "  - files: [\"other.yaml\"]\n    limits: { max_pdos: 1 }\n"
                                     "  - product_codes: [0x10]\n    limits: { max_pdos: { rx: 2 } }\n"
                                     "  - product_codes: [0x11]\n    limits: { max_pdos: { rx: 1 } }\n");
    const auto found = check(three_rx_pdos, (dir / "device.yaml").string(), dir / "profile.yaml");
    ASSERT_EQ(found.size(), 1u) << describe(found);  // rx: 2 for product code 0x10, not 1
    EXPECT_EQ(found.items()[0].rule, "profile-max-pdos");
    EXPECT_NE(found.items()[0].message.find("at most 2"), std::string::npos);
}

TEST(EnforceLimits, AnUnusableConfigIsAnErrorInTheConfig) {
    TempDir dir;
    write_text(dir / "bad.yaml", "limits:\n  max_pdo: 4\n");
    const auto found = check(three_rx_pdos, "device.yaml", dir / "bad.yaml");
    ASSERT_TRUE(found.has_errors());
    EXPECT_EQ(found.items()[0].path, (dir / "bad.yaml").string());
    EXPECT_EQ(found.items()[0].pos.line, 2u);
    const auto missing = check(three_rx_pdos, "device.yaml", dir / "none.yaml");
    ASSERT_TRUE(missing.has_errors());
    EXPECT_EQ(missing.items()[0].path, (dir / "none.yaml").string()) << describe(missing);
}

// Two revisions of one product code, each with two RxPDOs and its own limits.
std::string revision(int number, int max_rx_pdos) {
    return "  - type: EX\n"
           "    name: EX rev " + std::to_string(number) + "\n"
           "    product_code: 0x10\n"
           "    revision: " + std::to_string(number) + "\n"
           "    group: G\n"
           "    mailbox: { size: 128, coe: { sdo_info: false } }\n"
           "    objects:\n"
           "      0x7000: { name: Out, type: USINT, access: rw, pdo: rx }\n"
           "    rxpdo:\n"
           "      - { index: 0x1600, entries: [0x7000] }\n"
           "      - { index: 0x1601, assigned: false, entries: [] }\n"
           "    limits: { max_pdos: { rx: " + std::to_string(max_rx_pdos) + " } }\n";
}

const std::string two_revisions = "vendor: { id: 0xE4, name: Example }\ndevices:\n" + revision(1, 1) + revision(2, 2);

TEST(EnforceLimits, EachRevisionIsHeldToItsOwnLimits) {
    const auto found = check(two_revisions);
    EXPECT_EQ(findings(found, "profile-max-pdos"), (std::set<Where>{{line_of(two_revisions, "index: 0x1601"), 9}})) << describe(found);
}

TEST(EnforceLimits, OnlyTheSelectedDevicesAreChecked) {
    EXPECT_TRUE(check(two_revisions, "device.yaml", {}, esi::DeviceSelector{0x10, 2}).empty());
    EXPECT_EQ(check(two_revisions, "device.yaml", {}, esi::DeviceSelector{0x10, 1}).size(), 1u);
}

}  // namespace
