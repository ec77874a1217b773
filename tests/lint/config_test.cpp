#include <gtest/gtest.h>

#include "esi/lint/config.hpp"
#include "support/test_support.hpp"

using esi::test::TempDir;
using esi::test::write_text;

TEST(LintConfig, ReadsRulesLimitsAndOverrides) {
    TempDir dir;
    write_text(dir / ".esi-lint.yaml", R"(
rules:
  xml-hex-prefix: off
limits:
  max_pdos: { rx: 4, tx: 4 }
  pdo_index_ranges: { rx: ["0x1600-0x1603"], tx: [[0x1A00, 0x1A03]] }
  max_entries_per_pdo: 6
  bitlen: [8, 16, 32]
  fixed_sm: { 0: MBoxOut, 1: MBoxIn, 2: Outputs, 3: Inputs }
  transitions: [IP, PS]
overrides:
  - files: ["legacy/*.xml"]
    rules: { xml-hex-prefix: error }
  - product_codes: [0x264860d2]
    limits: { max_entries_per_pdo: 8 }
)");
    const auto result = esi::load_lint_config(dir / ".esi-lint.yaml");
    ASSERT_TRUE(result.config) << (result.diagnostics.empty() ? "" : result.diagnostics.items()[0].message);
    const auto& c = *result.config;
    EXPECT_EQ(c.rules.at("xml-hex-prefix"), esi::RuleSetting::off);
    EXPECT_EQ(c.limits.max_rx_pdos, 4u);
    ASSERT_EQ(c.limits.rx_pdo_ranges.size(), 1u);
    EXPECT_EQ(c.limits.rx_pdo_ranges[0].first, 0x1600u);
    EXPECT_EQ(c.limits.rx_pdo_ranges[0].last, 0x1603u);
    EXPECT_EQ(c.limits.tx_pdo_ranges[0].last, 0x1A03u);
    EXPECT_EQ(c.limits.allowed_bit_lens, (std::vector<std::uint32_t>{8, 16, 32}));
    EXPECT_EQ(c.limits.fixed_sms.at(2), "Outputs");

    const auto plain = esi::effective_config(c, dir / "device.xml");
    EXPECT_EQ(plain.severity_of("xml-hex-prefix", esi::Severity::warning), std::nullopt);
    const auto legacy = esi::effective_config(c, dir / "legacy" / "old.xml");
    EXPECT_EQ(legacy.severity_of("xml-hex-prefix", esi::Severity::warning), esi::Severity::error);
    EXPECT_EQ(plain.limits_for(0x264860d2u).max_entries_per_pdo, 8u);
    EXPECT_EQ(plain.limits_for(0x1u).max_entries_per_pdo, 6u);
}

TEST(LintConfig, UnknownKeysAndRulesAreLocatedWithSuggestion) {
    TempDir dir;
    write_text(dir / "c.yaml", "rules:\n  xml-hex-prefx: off\nlimit:\n  max_pdos: 4\n");
    const auto result = esi::load_lint_config(dir / "c.yaml");
    EXPECT_FALSE(result.config);
    ASSERT_EQ(result.diagnostics.size(), 2u);
    EXPECT_EQ(result.diagnostics.items()[0].pos.line, 2u);
    EXPECT_NE(result.diagnostics.items()[0].message.find("did you mean 'xml-hex-prefix'"), std::string::npos);
    EXPECT_EQ(result.diagnostics.items()[1].pos.line, 3u);
    EXPECT_NE(result.diagnostics.items()[1].message.find("did you mean 'limits'"), std::string::npos);
}

TEST(LintConfig, ExtendsIsRelativeAndLaterWins) {
    TempDir dir;
    write_text(dir / "profiles" / "base.yaml", "limits:\n  max_entries_per_pdo: 6\n  bitlen: [8]\n");
    write_text(dir / "c.yaml", "extends: profiles/base.yaml\nlimits:\n  bitlen: [8, 16]\n");
    const auto result = esi::load_lint_config(dir / "c.yaml");
    ASSERT_TRUE(result.config);
    EXPECT_EQ(result.config->limits.max_entries_per_pdo, 6u);
    EXPECT_EQ(result.config->limits.allowed_bit_lens.size(), 2u);
}

TEST(LintConfig, ExtendsCycleIsAnError) {
    TempDir dir;
    write_text(dir / "a.yaml", "extends: b.yaml\n");
    write_text(dir / "b.yaml", "extends: a.yaml\n");
    const auto result = esi::load_lint_config(dir / "a.yaml");
    EXPECT_FALSE(result.config);
}

TEST(LintConfig, YamlSyntaxErrorHasPosition) {
    TempDir dir;
    write_text(dir / "c.yaml", "rules:\n  a: [unclosed\n");
    const auto result = esi::load_lint_config(dir / "c.yaml");
    EXPECT_FALSE(result.config);
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_GT(result.diagnostics.items()[0].pos.line, 0u);
}

TEST(LintConfig, NearestConfigUpwards) {
    TempDir dir;
    write_text(dir / ".esi-lint.yaml", "{}\n");
    std::filesystem::create_directories(dir / "a" / "b");
    const auto found = esi::find_config_for(dir / "a" / "b" / "x.xml");
    ASSERT_TRUE(found);
    EXPECT_EQ(std::filesystem::canonical(*found), std::filesystem::canonical(dir / ".esi-lint.yaml"));
}

TEST(LintConfig, DuplicateKeysAreErrorsNotTheLastValue) {
    TempDir dir;
    write_text(dir / "c.yaml", "rules:\n  xml-hex-prefix: off\n  xml-hex-prefix: error\n");
    const auto result = esi::load_lint_config(dir / "c.yaml");
    EXPECT_FALSE(result.config);
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_EQ(result.diagnostics.items()[0].pos.line, 3u);
    EXPECT_EQ(result.diagnostics.items()[0].pos.column, 3u);
}

TEST(LintConfig, LimitsAreReadLikeInADeviceSource) {
    // The same messages, rule ids and positions as `limits:` in a YAML device source
    // (tests/yaml/bad_input_test.cpp): one reader serves both.
    TempDir dir;
    write_text(dir / "c.yaml", "limits:\n  max_pdo: 4\n  bitlen: [8, 16, sixteen]\n");
    const auto result = esi::load_lint_config(dir / "c.yaml");
    EXPECT_FALSE(result.config);
    ASSERT_EQ(result.diagnostics.size(), 2u);
    const auto& unknown = result.diagnostics.items()[0];
    EXPECT_EQ(unknown.rule, "yaml-unknown-key");
    EXPECT_EQ(unknown.pos.line, 2u);
    EXPECT_EQ(unknown.pos.column, 3u);
    EXPECT_NE(unknown.message.find("did you mean 'max_pdos'?"), std::string::npos);
    const auto& bad_number = result.diagnostics.items()[1];
    EXPECT_EQ(bad_number.rule, "yaml-type");
    EXPECT_EQ(bad_number.pos.line, 3u);
    EXPECT_EQ(bad_number.pos.column, 19u);
}

TEST(LintConfig, AProfileExtendedTwiceIsNotACycle) {
    TempDir dir;
    write_text(dir / "base.yaml", "limits:\n  max_entries_per_pdo: 6\n");
    write_text(dir / "a.yaml", "extends: base.yaml\n");
    write_text(dir / "b.yaml", "extends: base.yaml\n");
    write_text(dir / "c.yaml", "extends: [a.yaml, b.yaml]\n");
    const auto result = esi::load_lint_config(dir / "c.yaml");
    ASSERT_TRUE(result.config) << (result.diagnostics.empty() ? "" : result.diagnostics.items()[0].message);
    EXPECT_EQ(result.config->limits.max_entries_per_pdo, 6u);
}

TEST(LintConfig, AnEmptyFileConfiguresNothing) {
    TempDir dir;
    write_text(dir / "c.yaml", "# nothing yet\n");
    const auto result = esi::load_lint_config(dir / "c.yaml");
    ASSERT_TRUE(result.config);
    EXPECT_TRUE(result.config->rules.empty());
}
