#pragma once
// esi-lint's verdicts on the real corpus as a table (file, rule, severity -> number of findings),
// the reviewed snapshot of it (tests/corpus/expected/verdicts.tsv), and the short account of how
// two tables differ that a reviewer reads before accepting a new snapshot: per rule +N/-N
// findings, and the files whose pass/fail under `--fail-on error` flips.

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <tuple>

namespace esi::test {

// (file relative to the corpus folder, rule id, severity) -> findings.
using VerdictKey = std::tuple<std::string, std::string, std::string>;
using VerdictTable = std::map<VerdictKey, std::size_t>;

// The TSV form: a header line, then one "file<TAB>rule<TAB>severity<TAB>count" line per key, in
// key order; lines starting with '#' are comments.
[[nodiscard]] VerdictTable parse_verdicts(std::string_view tsv);
[[nodiscard]] std::string format_verdicts(const VerdictTable& table);

// Builds the table from `esi-lint --format json` output; paths are made relative to `corpus_dir`.
[[nodiscard]] VerdictTable verdicts_from_lint_json(std::string_view json, const std::string& corpus_dir);

// tests/corpus/expected/origins.tsv: file -> origin ("official", "example", "hobby", ...).
// "official" marks a device vendor's file as the vendor ships it; issue 10's precision figures
// are taken over those.
using Origins = std::map<std::string, std::string>;
[[nodiscard]] Origins parse_origins(std::string_view tsv);

// The files that fail `--fail-on error` (at least one error finding).
[[nodiscard]] std::set<std::string> failing_files(const VerdictTable& table);

// Official files failing, and error findings on official files.
struct OfficialFigures {
    std::size_t official_files = 0;
    std::size_t failing = 0;
    std::size_t error_findings = 0;
};
[[nodiscard]] OfficialFigures official_figures(const VerdictTable& table, const Origins& origins);

// The review text for a change from `snapshot` to `now` (a one-line account when equal).
[[nodiscard]] std::string describe_change(const VerdictTable& snapshot, const VerdictTable& now, const Origins& origins);

}  // namespace esi::test
