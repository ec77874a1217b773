// The verdict table and the account a reviewer reads (no corpus needed).

#include <gtest/gtest.h>

#include <algorithm>

#include "corpus/verdict_table.hpp"

namespace {

using esi::test::VerdictTable;

const esi::test::Origins origins = esi::test::parse_origins(
    "file\torigin\twhy\n"
    "a.xml\tofficial\tvendor\n"
    "b.xml\thobby\tproject\n");

TEST(VerdictTable, TsvRoundTripsAndSkipsComments) {
    const VerdictTable table{{{"a.xml", "sm-overlap", "error"}, 2}, {{"b.xml", "od-bitsize", "warning"}, 1}};
    EXPECT_EQ(esi::test::parse_verdicts("# reviewed\n" + esi::test::format_verdicts(table)), table);
    EXPECT_EQ(esi::test::format_verdicts(table),
              "file\trule\tseverity\tcount\na.xml\tsm-overlap\terror\t2\nb.xml\tod-bitsize\twarning\t1\n");
}

TEST(VerdictTable, LintJsonPathsBecomeCorpusRelative) {
    const auto table = esi::test::verdicts_from_lint_json(
        R"({"diagnostics":[{"path":"/c/esi/a.xml","rule":"sm-overlap","severity":"error"},
                           {"path":"/c/esi/a.xml","rule":"sm-overlap","severity":"error"}]})",
        "/c/esi");
    EXPECT_EQ(table, (VerdictTable{{{"a.xml", "sm-overlap", "error"}, 2}}));
}

TEST(VerdictTable, OfficialFiguresCountOnlyOfficialFiles) {
    const VerdictTable table{{{"a.xml", "sm-overlap", "error"}, 2},
                             {{"a.xml", "od-bitsize", "warning"}, 5},
                             {{"b.xml", "sm-overlap", "error"}, 7}};
    const auto figures = esi::test::official_figures(table, origins);
    EXPECT_EQ(figures.official_files, 1u);
    EXPECT_EQ(figures.failing, 1u);
    EXPECT_EQ(figures.error_findings, 2u);
}

TEST(VerdictTable, AccountShowsPerRuleCountsAndFlippedFiles) {
    // A re-grade: a.xml's only error becomes a warning, so a.xml passes --fail-on error.
    const VerdictTable snapshot{{{"a.xml", "pdo-entry-object-bitlen", "error"}, 3}, {{"b.xml", "sm-overlap", "error"}, 1}};
    const VerdictTable now{{{"a.xml", "pdo-entry-object-bitlen", "warning"}, 3}, {{"b.xml", "sm-overlap", "error"}, 1}};
    const std::string account = esi::test::describe_change(snapshot, now, origins);
    EXPECT_NE(account.find("+0/-3       pdo-entry-object-bitlen         error    3 -> 0"), std::string::npos) << account;
    EXPECT_NE(account.find("+3/-0       pdo-entry-object-bitlen         warning  0 -> 3"), std::string::npos) << account;
    EXPECT_EQ(account.find("sm-overlap"), std::string::npos) << "unchanged rules are not listed\n" << account;
    EXPECT_NE(account.find("FAIL -> pass  a.xml  (official)"), std::string::npos) << account;
    EXPECT_NE(account.find("failing --fail-on error: 1 -> 0 of 1"), std::string::npos) << account;
}

TEST(VerdictTable, AccountOfAnUnchangedTableIsOneLine) {
    const VerdictTable table{{{"a.xml", "sm-overlap", "error"}, 2}};
    const std::string account = esi::test::describe_change(table, table, origins);
    EXPECT_EQ(account.rfind("esi-lint corpus verdicts match the snapshot: 2 findings (2 errors) in 1 files", 0), 0u) << account;
    EXPECT_EQ(std::count(account.begin(), account.end(), '\n'), 1);
}

}  // namespace
