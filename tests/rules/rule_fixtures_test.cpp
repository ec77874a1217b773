// Every rule with a check has a fixture folder tests/rules/fixtures/<rule-id>/ holding
//   bad.xml   - the rule must fire exactly on the lines marked <!-- expect: <rule-id> -->
//   good.xml  - the rule must stay silent
//   bad-<case>.xml, good-<case>.xml (optional) - more cases of either kind, e.g. cut from a real
//               vendor file: each is held to the same expectation
//   config.yaml (optional) - an .esi-lint.yaml applied to all of them (for profile-* rules)
// This test enumerates the catalogue, so a new rule without fixtures fails here.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "esi/check/registry.hpp"
#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::read_text;

std::filesystem::path fixture_dir(std::string_view id) {
    return esi::test::source_dir() / "tests" / "rules" / "fixtures" / std::string(id);
}

esi::EffectiveConfig config_for(const std::filesystem::path& dir, const std::filesystem::path& file) {
    const auto config_path = dir / "config.yaml";
    if (!std::filesystem::exists(config_path)) return {};
    esi::ConfigResult loaded = esi::load_lint_config(config_path);
    EXPECT_TRUE(loaded.config) << "fixture config does not load: " << config_path;
    if (!loaded.config) return {};
    return esi::effective_config(*loaded.config, file);
}

std::set<std::uint32_t> lines_of(const esi::FileReport& report, std::string_view rule) {
    std::set<std::uint32_t> lines;
    for (const auto& d : report.diagnostics)
        if (d.rule == rule) lines.insert(d.pos.line);
    return lines;
}

std::set<std::uint32_t> expected_lines(const std::string& text, std::string_view rule) {
    std::set<std::uint32_t> lines;
    std::istringstream in(text);
    std::string line;
    std::uint32_t number = 0;
    const std::string marker = "expect: " + std::string(rule) + " ";
    const std::string marker_end = "expect: " + std::string(rule) + "-->";
    while (std::getline(in, line)) {
        ++number;
        if (line.find(marker) != std::string::npos || line.find(marker_end) != std::string::npos) lines.insert(number);
    }
    return lines;
}

std::string describe(const esi::FileReport& report) {
    std::string out;
    for (const auto& d : report.diagnostics)
        out += "  " + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.rule + ": " + d.message + "\n";
    return out;
}

class RuleFixture : public ::testing::TestWithParam<std::string> {};

// bad.xml, bad-*.xml or good.xml, good-*.xml of a fixture folder, sorted by name.
std::vector<std::filesystem::path> fixture_files(const std::filesystem::path& dir, std::string_view kind) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".xml") continue;
        if (name == std::string(kind) + ".xml" || name.starts_with(std::string(kind) + "-")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST_P(RuleFixture, FiresOnBadAndStaysSilentOnGood) {
    const std::string id = GetParam();
    const auto dir = fixture_dir(id);
    ASSERT_TRUE(std::filesystem::exists(dir / "bad.xml")) << "rule " << id << " has no fixture " << dir / "bad.xml";
    ASSERT_TRUE(std::filesystem::exists(dir / "good.xml")) << "rule " << id << " has no fixture " << dir / "good.xml";

    for (const auto& path : fixture_files(dir, "bad")) {
        SCOPED_TRACE(path.filename().string());
        const std::string bad_text = read_text(path);
        const auto bad = esi::lint_bytes(bad_text, path.string(), config_for(dir, path));
        const auto expected = expected_lines(bad_text, id);
        ASSERT_FALSE(expected.empty()) << path.filename() << " of " << id << " marks no line with <!-- expect: " << id << " -->";
        EXPECT_EQ(lines_of(bad, id), expected) << "diagnostics on " << path.filename() << ":\n" << describe(bad);
        for (const auto& d : bad.diagnostics) EXPECT_NE(d.rule, "xml-syntax") << "fixture is not well-formed: " << d.message;
    }
    for (const auto& path : fixture_files(dir, "good")) {
        SCOPED_TRACE(path.filename().string());
        const auto good = esi::lint_bytes(read_text(path), path.string(), config_for(dir, path));
        EXPECT_TRUE(lines_of(good, id).empty()) << "diagnostics on " << path.filename() << ":\n" << describe(good);
        for (const auto& d : good.diagnostics) EXPECT_NE(d.rule, "xml-syntax") << "fixture is not well-formed: " << d.message;
    }
}

std::vector<std::string> checked_rules() {
    std::vector<std::string> ids;
    for (const auto& rule : esi::all_rules())
        if (rule.check) ids.emplace_back(rule.id);
    return ids;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, RuleFixture, ::testing::ValuesIn(checked_rules()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(RuleFixture);

TEST(RuleCatalogue, IdsAreUniqueKebabCaseWithKnownAreaPrefix) {
    static const std::set<std::string> areas = {"xml", "identity", "sm", "fmmu", "pdo", "od", "mailbox", "initcmd",
                                                "dc", "eeprom", "deprecated", "profile", "lint"};
    std::set<std::string> seen;
    for (const auto& rule : esi::all_rules()) {
        const std::string id(rule.id);
        EXPECT_TRUE(seen.insert(id).second) << "duplicate rule id " << id;
        EXPECT_TRUE(areas.count(id.substr(0, id.find('-')))) << id << " has no known area prefix";
        for (char c : id) EXPECT_TRUE((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-') << id;
        EXPECT_FALSE(rule.summary.empty()) << id;
        EXPECT_GT(rule.rationale.size(), 60u) << id << ": the rationale must explain and cite a source";
        EXPECT_FALSE(rule.bad_example.empty()) << id;
        EXPECT_FALSE(rule.good_example.empty()) << id;
    }
}

// Rationales cite what a user can open: ETG documents, public projects and issues, vendor manuals
// by name and section. These phrases point at notes and data sets only the authors have.
TEST(RuleCatalogue, RationalesCiteNoInternalNotes) {
    static const std::string_view internal[] = {"domain note", "gen_od", "seed ", "servo manuals", "the corpus"};
    for (const auto& rule : esi::all_rules())
        for (const auto phrase : internal)
            EXPECT_EQ(rule.rationale.find(phrase), std::string_view::npos) << rule.id << " cites '" << phrase << "'";
}

// One rule in one place (libesi/src/check/areas.hpp): each rule's Rule constant is defined once,
// in a rules file of its area (rules_<area>.cpp or rules_<area>_<topic>.cpp), where its check
// function is. Front-end rules without a check (xml-…, lint-directive) may live in any rules file.
TEST(RuleCatalogue, EachRuleIsDefinedOnceInARulesFileOfItsArea) {
    const auto dir = esi::test::source_dir() / "libesi" / "src" / "check";
    std::map<std::string, std::vector<std::string>> files_of;  // rule id -> rules files defining it
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string file = entry.path().filename().string();
        if (!file.starts_with("rules_") || entry.path().extension() != ".cpp") continue;
        const std::string text = read_text(entry.path());
        const std::string key = ".id = \"";
        for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
            const auto begin = at + key.size();
            files_of[text.substr(begin, text.find('"', begin) - begin)].push_back(file);
        }
    }
    for (const auto& rule : esi::all_rules()) {
        const std::string id(rule.id);
        const auto& files = files_of[id];
        ASSERT_EQ(files.size(), 1u) << id << " must be defined in exactly one libesi/src/check/rules_*.cpp";
        if (!rule.check) continue;
        const std::string area = id.substr(0, id.find('-'));
        EXPECT_TRUE(files[0] == "rules_" + area + ".cpp" || files[0].starts_with("rules_" + area + "_"))
            << id << " is defined in " << files[0] << ", not in a rules file of its area " << area;
    }
}

}  // namespace
