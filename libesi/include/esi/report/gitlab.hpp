#pragma once
// esi-lint's report as a GitLab Code Quality report (artifacts:reports:codequality): a JSON
// array of issues in the subset of the Code Climate format GitLab reads — description,
// check_name, fingerprint, severity, location.path (relative to the repository root) and
// location.lines.begin. Severities: info → info, warning → minor, error → major; a file that
// could not be read or a broken config → blocker (GitLab has no channel for tool errors, and
// the job fails on esi-lint's exit code 2 anyway).

#include <filesystem>
#include <string>

#include "esi/lint/lint.hpp"

namespace esi {

// `source_root`: the repository root the paths are made relative to (esi-lint: the current
// directory, where CI runs it).
[[nodiscard]] std::string render_gitlab(const LintReport& report, const std::filesystem::path& source_root);

}  // namespace esi
