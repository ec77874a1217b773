#pragma once
// What code-scanning services (GitHub code scanning via SARIF, GitLab Code Quality) need to
// recognise a finding from run to run: the file as a path in the repository, a fingerprint that
// survives unrelated edits of the file, and which diagnostics are the tool's own problems.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "esi/lint/lint.hpp"

namespace esi::report_detail {

// `path` relative to `root` (generic form, '/' separated) when it lies inside it; otherwise the
// absolute path; a pseudo path such as <stdin> as it is.
[[nodiscard]] std::string repository_path(const std::string& path, const std::filesystem::path& root);

// Whether a file's diagnostic says the run could not do its work (the file could not be read)
// rather than something about the file's content. Such diagnostics, and every config or schema
// problem (LintReport::config_diagnostics), are the tool's, not findings to track.
[[nodiscard]] inline bool is_execution_problem(const FileReport& file, const Diagnostic& d) {
    return file.unreadable && d.rule == "io-error";
}

// Fingerprints of the findings of one report: a hash of the rule id, the repository path and the
// whitespace-normalised text of the finding's line (its message when it has no line), and the
// number of the occurrence among identical ones. Lines added above a finding and re-indenting
// keep it; editing its line or moving it to another file makes it new.
class Fingerprints {
public:
    [[nodiscard]] std::string next(const Diagnostic& d, const std::string& repository_path,
                                   const std::map<std::uint32_t, std::string>& quoted_lines);

private:
    std::map<std::string, int> seen_;
};

}  // namespace esi::report_detail
