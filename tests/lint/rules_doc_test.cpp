// docs/rules.md is the rendered rule catalogue followed by the requirement table, which is written
// by hand (it maps specification requirements to rules, which no catalogue field holds). This test
// fails when a rule changes without the document. Regenerate the catalogue part, keeping the table,
// with: ESI_UPDATE_GOLDEN=1 ./build/tests/lint_tests --gtest_filter=RulesDoc.*

#include <gtest/gtest.h>

#include <cstdlib>

#include "esi/report/lint_output.hpp"
#include "lint/requirement_table.hpp"
#include "support/test_support.hpp"

TEST(RulesDoc, DocsRulesMdMatchesTheCatalogue) {
    const auto path = esi::test::source_dir() / "docs" / "rules.md";
    const std::string rendered = esi::render_rule_list_markdown();
    const esi::test::RulesDocParts parts = esi::test::split_rules_doc(esi::test::read_text(path));
    if (esi::test::rewrite_golden(path, rendered + parts.requirement_table)) GTEST_SKIP() << path << " rewritten";
    EXPECT_EQ(parts.catalogue, rendered) << "docs/rules.md is out of date; regenerate it (see the comment in this test)";
}
