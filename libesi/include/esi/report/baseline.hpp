#pragma once
// A baseline: the findings a catalogue already had when esi-lint was adopted, so that CI fails on
// new findings only while the old ones are worked off (ruff's and clang-tidy's way in).
//
// `esi-lint --write-baseline FILE` writes every finding of the run; `--baseline FILE` drops the
// findings it holds from the report (neither printed nor counted). A finding is matched by its
// rule, its file (relative to the source root, as in SARIF) and the fingerprint SARIF gives it
// (report/finding_identity.hpp): lines added above it keep it matched, editing its own line makes
// it new. A file that cannot be read is never baselined: it is not a finding.
//
//   {"esi-lint-baseline": 1,
//    "findings": [{"rule": "xml-hex-prefix", "path": "devices/io.xml",
//                  "fingerprint": "1f2e…:1", "message": "…"}]}
//
// The message is there for the reviewer of the baseline; matching ignores it.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>

#include "esi/lint/lint.hpp"

namespace esi {

struct Baseline {
    std::set<std::tuple<std::string, std::string, std::string>> findings;  // rule, path, fingerprint
};

// The findings of `report` as a baseline file (deterministic: in report order).
[[nodiscard]] std::string render_baseline(const LintReport& report, const std::filesystem::path& source_root);

// nullopt and `error` when the text is not a baseline file.
[[nodiscard]] std::optional<Baseline> parse_baseline(std::string_view text, std::string& error);

// Drops the findings `baseline` holds from the report and counts them in report.baselined.
void apply_baseline(LintReport& report, const Baseline& baseline, const std::filesystem::path& source_root);

}  // namespace esi
