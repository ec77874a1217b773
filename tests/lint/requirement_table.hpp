#pragma once
// docs/rules.md in its two parts: the rule catalogue rendered from the registry, and the
// requirement table written by hand after it (from the line "## Requirement table" on).

#include <string>

namespace esi::test {

struct RulesDocParts {
    std::string catalogue;          // up to and including the blank line before the table
    std::string requirement_table;  // from "## Requirement table" to the end; empty when absent
};

inline RulesDocParts split_rules_doc(const std::string& text) {
    const std::string marker = "\n\n## Requirement table\n";
    const auto at = text.find(marker);
    if (at == std::string::npos) return {text, {}};
    return {text.substr(0, at + 1), text.substr(at + 1)};
}

}  // namespace esi::test
