// docs/esi-diff.md prints the classification table; it must list every kind with the class the
// code gives it, so that the documentation cannot drift from the table in classification.cpp.

#include <gtest/gtest.h>

#include "esi/diff/classification.hpp"
#include "support/test_support.hpp"

TEST(DiffDocs, ListsEveryKindWithItsClass) {
    const std::string doc = esi::test::read_text(esi::test::source_dir() / "docs" / "esi-diff.md");
    ASSERT_FALSE(doc.empty());
    for (const auto& k : esi::change_kinds()) {
        const std::string row = "| `" + std::string(k.id) + "` | " + std::string(esi::to_string(k.change_class)) + " |";
        EXPECT_NE(doc.find(row), std::string::npos) << "docs/esi-diff.md lacks the row " << row;
    }
}
