// The requirement table of docs/rules.md: every row maps a requirement of the specifications to
// the rules that check it, or says why nothing checks it. A row naming a rule the catalogue does
// not hold (renamed, removed, mistyped) or a row with neither a rule nor a reason fails here.

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <vector>

#include "esi/check/registry.hpp"
#include "lint/requirement_table.hpp"
#include "support/test_support.hpp"

namespace {

struct Row {
    int line = 0;
    std::string checked_by;  // the last cell
};

// The table rows (lines starting with '|', past the header and separator lines) of the table part.
std::vector<Row> requirement_rows(const std::string& table) {
    std::vector<Row> rows;
    std::istringstream in(table);
    std::string line;
    int number = 0;
    bool header = true;  // the next '|' line is a header
    while (std::getline(in, line)) {
        ++number;
        if (!line.starts_with("|")) {
            header = true;
            continue;
        }
        if (header || line.starts_with("|---") || line.starts_with("| ---")) {
            header = false;
            continue;
        }
        const auto end = line.find_last_of('|');
        const auto start = line.find_last_of('|', end == 0 ? 0 : end - 1);
        if (end == std::string::npos || start == std::string::npos || start >= end) continue;
        rows.push_back({number, line.substr(start + 1, end - start - 1)});
    }
    return rows;
}

std::string rules_doc_table() {
    return esi::test::split_rules_doc(esi::test::read_text(esi::test::source_dir() / "docs" / "rules.md")).requirement_table;
}

}  // namespace

TEST(RequirementTable, IsThereAndHasRows) {
    const auto rows = requirement_rows(rules_doc_table());
    EXPECT_GT(rows.size(), 100u) << "docs/rules.md has no requirement table after the catalogue (\"## Requirement table\")";
}

TEST(RequirementTable, EveryRowNamesExistingRulesOrSaysWhyNot) {
    const std::regex rule_id("`([a-z0-9]+(-[a-z0-9]+)+)`");
    for (const Row& row : requirement_rows(rules_doc_table())) {
        SCOPED_TRACE("docs/rules.md requirement table, line " + std::to_string(row.line) + " of the table:" + row.checked_by);
        const bool not_checked = row.checked_by.find("not checked") != std::string::npos;
        int ids = 0;
        for (std::sregex_iterator it(row.checked_by.begin(), row.checked_by.end(), rule_id), end; it != end; ++it) {
            ++ids;
            EXPECT_NE(esi::find_rule((*it)[1].str()), nullptr) << "no rule " << (*it)[1].str() << " in the catalogue";
        }
        if (not_checked) {
            // "not checked, because …" with a reason of some length.
            const auto because = row.checked_by.find("because");
            EXPECT_NE(because, std::string::npos) << "a row not checked must say why (\"not checked, because …\")";
            if (because != std::string::npos) {
                EXPECT_GT(row.checked_by.size() - because, 20u) << "the reason is empty";
            }
        } else {
            EXPECT_GT(ids, 0) << "a row must name the rule that checks it or say \"not checked, because …\"";
        }
    }
}
