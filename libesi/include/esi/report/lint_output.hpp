#pragma once
// Renders a lint report as text (file:line:col: severity: message [rule] with the source line),
// JSON or GitHub workflow annotations (SARIF: esi/report/sarif.hpp). Pure functions: the CLI
// prints the string.

#include <string>

#include "esi/lint/lint.hpp"

namespace esi {

struct TextOutputOptions {
    bool show_source = true;  // quote the offending line with a caret
    bool color = false;
};

[[nodiscard]] std::string render_text(const LintReport& report, const TextOutputOptions& options = {});
// {"diagnostics":[{path,line,column,severity,rule,message,notes?,fix?}],"skipped":[{path,reason}],
//  "summary":{files,errors,warnings,infos}}; fix: {description, edits:[{offset,length,replacement}]},
// offsets into the file's decoded UTF-8 text.
[[nodiscard]] std::string render_json(const LintReport& report);
[[nodiscard]] std::string render_github(const LintReport& report);

// The rule catalogue: text (id, severity, summary) or JSON (every field).
[[nodiscard]] std::string render_rule_list_text();
[[nodiscard]] std::string render_rule_list_json();
// The catalogue as a Markdown document (docs/rules.md is this, kept in sync by a test).
[[nodiscard]] std::string render_rule_list_markdown();
// One rule in full: rationale, bad and good example. Empty when the id is unknown.
[[nodiscard]] std::string render_rule_explanation(std::string_view rule_id);

}  // namespace esi
