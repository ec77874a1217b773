// docs/rules.md is the rendered rule catalogue; this test fails when a rule changes without the
// document. Regenerate with: ESI_UPDATE_GOLDEN=1 ./build/tests/lint_tests --gtest_filter=RulesDoc.*

#include <gtest/gtest.h>

#include <cstdlib>

#include "esi/report/lint_output.hpp"
#include "support/test_support.hpp"

TEST(RulesDoc, DocsRulesMdMatchesTheCatalogue) {
    const auto path = esi::test::source_dir() / "docs" / "rules.md";
    const std::string rendered = esi::render_rule_list_markdown();
    if (std::getenv("ESI_UPDATE_GOLDEN")) esi::test::write_text(path, rendered);
    EXPECT_EQ(esi::test::read_text(path), rendered) << "docs/rules.md is out of date; regenerate it (see the comment in this test)";
}
