// The `limits:` keys for device facts (mailbox protocols, ESC resources, PDO ownership and names,
// parameter addressing, SYNC0 cycle): read into esi::Limits from a device source, merged field by
// field, and every mistake reported at its line:column like any other key.

#include <gtest/gtest.h>

#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::describe;
using esi::test::load_yaml;

namespace {

const std::string header = R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - type: D
    name: Device
    product_code: 1
    revision: 2
    mailbox: { size: 128, coe: true }
    limits:
)";  // 9 lines; the limits' keys start on line 10, column 7

Limits limits_of(const std::string& body) {
    const DeviceSource s = load_yaml(header + body);
    EXPECT_TRUE(s.diagnostics.empty()) << describe(s.diagnostics);
    return s.device_limits.empty() ? Limits{} : s.device_limits.front().second;
}

// Exactly one error, with this rule, at line:col, whose message holds `fragment`.
void expect_error(const std::string& body, const std::string& rule, std::uint32_t line, std::uint32_t column,
                  const std::string& fragment) {
    const DeviceSource s = load_yaml(header + body);
    EXPECT_FALSE(s.document);
    ASSERT_EQ(s.diagnostics.count(Severity::error), 1u) << describe(s.diagnostics);
    const Diagnostic& d = *std::find_if(s.diagnostics.begin(), s.diagnostics.end(),
                                        [](const Diagnostic& x) { return x.severity == Severity::error; });
    EXPECT_EQ(d.rule, rule) << describe(s.diagnostics);
    EXPECT_EQ(d.pos.line, line) << describe(s.diagnostics);
    EXPECT_EQ(d.pos.column, column) << describe(s.diagnostics);
    EXPECT_NE(d.message.find(fragment), std::string::npos) << d.message;
}

}  // namespace

TEST(YamlLimitsKeys, ReadsEveryDeviceFact) {
    const Limits l = limits_of(R"(      mailbox_protocols: [CoE, VoE]
      max_fmmus: 4
      max_sms: 6
      pdo_assign: false
      pdo_config: false
      pdo_names: { rx: Outputs, tx: Inputs }
      parameter_index: { base: 0x2000, group_size: 0x200, groups: A-Z }
      sync0_cycle: { min_ns: 1000000, multiple_of_ns: 1000000, factors: [1, 2, -2] }
)");
    EXPECT_EQ(l.mailbox_protocols, (std::vector<std::string>{"CoE", "VoE"}));
    EXPECT_EQ(l.max_fmmus, 4u);
    EXPECT_EQ(l.max_sms, 6u);
    EXPECT_EQ(l.pdo_assign, false);
    EXPECT_EQ(l.pdo_config, false);
    EXPECT_EQ(l.rx_pdo_name, "Outputs");
    EXPECT_EQ(l.tx_pdo_name, "Inputs");
    ASSERT_TRUE(l.parameter_index);
    EXPECT_EQ(*l.parameter_index, (ParameterIndexRule{0x2000, 0x200, 'A', 'Z'}));
    ASSERT_TRUE(l.sync0_cycle);
    EXPECT_EQ(*l.sync0_cycle, (Sync0CycleRule{1000000, 1000000, {1, 2, -2}}));
    EXPECT_FALSE(l.empty());
}

TEST(YamlLimitsKeys, EachFactAloneMakesTheLimitsNonEmpty) {
    for (const char* body : {"      mailbox_protocols: [CoE]\n", "      max_fmmus: 4\n", "      max_sms: 6\n", "      pdo_assign: false\n",
                             "      pdo_config: false\n", "      pdo_names: { tx: Inputs }\n",
                             "      parameter_index: { base: 0x2000, group_size: 0x200 }\n", "      sync0_cycle: { min_ns: 1 }\n"}) {
        SCOPED_TRACE(body);
        EXPECT_FALSE(limits_of(body).empty());
    }
}

TEST(YamlLimitsKeys, ParameterGroupsDefaultToAToZAndPlaceByFormula) {
    const Limits l = limits_of("      parameter_index: { base: 0x2000, group_size: 0x200 }\n");
    ASSERT_TRUE(l.parameter_index);
    const ParameterIndexRule& rule = *l.parameter_index;
    EXPECT_EQ(rule.index_of('A', 180), 0x20B4u);
    EXPECT_EQ(rule.index_of('Z', 511), 0x53FFu);
    EXPECT_FALSE(rule.index_of('A', 512));  // a line past its group
    EXPECT_FALSE(rule.index_of('a', 1));
    EXPECT_EQ(rule.end(), 0x5400u);
}

TEST(YamlLimitsKeys, LaterLimitsReplaceEarlierOnesFieldByField) {
    Limits base;
    base.mailbox_protocols = {"CoE"};
    base.max_fmmus = 4;
    base.sync0_cycle = Sync0CycleRule{1000000, std::nullopt, {}};
    Limits source;
    source.max_fmmus = 8;
    source.pdo_assign = false;
    base.merge(source);
    EXPECT_EQ(base.mailbox_protocols, (std::vector<std::string>{"CoE"}));
    EXPECT_EQ(base.max_fmmus, 8u);
    EXPECT_EQ(base.pdo_assign, false);
    EXPECT_EQ(base.sync0_cycle->min_ns, 1000000u);
}

TEST(YamlLimitsKeys, AnUnknownProtocolGetsADidYouMean) {
    expect_error("      mailbox_protocols: [CoE, FOE]\n", "yaml-type", 10, 32, "did you mean 'FoE'?");
}

TEST(YamlLimitsKeys, ParameterIndexNeedsBaseAndGroupSize) {
    expect_error("      parameter_index: { base: 0x2000 }\n", "yaml-missing-key", 10, 24, "group_size");
}

TEST(YamlLimitsKeys, ParameterGroupsAreUpperCaseLetters) {
    expect_error("      parameter_index: { base: 0x2000, group_size: 0x200, groups: a-z }\n", "yaml-type", 10, 67, "A-Z");
}

TEST(YamlLimitsKeys, ParameterGroupsMustEndWithinTheIndexRange) {
    expect_error("      parameter_index: { base: 0x5000, group_size: 0x800 }\n", "yaml-value", 10, 24, "past index 0xFFFF");
}

TEST(YamlLimitsKeys, ASync0GranularityOfZeroIsOutOfRange) {
    expect_error("      sync0_cycle: { multiple_of_ns: 0 }\n", "yaml-number-range", 10, 38, "multiple_of_ns");
}

TEST(YamlLimitsKeys, SubKeysAreCheckedLikeEveryOtherMapping) {
    expect_error("      sync0_cycle: { min_n: 1000000 }\n", "yaml-unknown-key", 10, 22, "did you mean 'min_ns'?");
    expect_error("      pdo_names: { rxpdo: Outputs }\n", "yaml-unknown-key", 10, 20, "rxpdo");
    expect_error("      pdo_assign: maybe\n", "yaml-type", 10, 19, "pdo_assign");
}
