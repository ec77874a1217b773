#pragma once
// What the editor shows of a lint: LSP Diagnostics (rule id as `code`, severity mapped, the
// --explain hint in `data`) and the code actions on them: the rule's safe fix (Diagnostic::fix,
// the one esi-lint --fix applies) as a quickfix, and "suppress this rule here" with the inline
// suppression comments esi-lint understands (esi/lint/suppression.hpp).

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"
#include "esi/lsp/lint_worker.hpp"
#include "esi/lsp/position.hpp"

namespace esi::lsp {

// The LSP Diagnostic of a finding in `text` (the text that was linted).
[[nodiscard]] nlohmann::json to_lsp_diagnostic(const Diagnostic& diagnostic, const LineIndex& index, std::string_view text,
                                               const std::string& uri);

// The params of textDocument/publishDiagnostics for a lint result.
[[nodiscard]] nlohmann::json publish_params(const LintResult& result);

// The code actions for the findings of `result` whose range meets `range`.
[[nodiscard]] nlohmann::json code_actions(const LintResult& result, Range range);

// The edit that suppresses `rule` for the finding on 1-based `line` of an XML text: a
// disable-next-line comment on a line of its own above it, or, when that line is inside a start
// tag that began earlier (a comment may not stand there), a disable/enable pair around the tag.
[[nodiscard]] std::vector<TextEdit> suppression_edits(std::string_view text, std::uint32_t line, const std::string& rule);

}  // namespace esi::lsp
