#include "esi/report/gitlab.hpp"

#include <nlohmann/json.hpp>

#include "report/finding_identity.hpp"

namespace esi {

namespace {

using ordered_json = nlohmann::ordered_json;

std::string_view gitlab_severity(Severity s) {
    switch (s) {
        case Severity::error: return "major";
        case Severity::warning: return "minor";
        case Severity::info: return "info";
    }
    return "minor";
}

}  // namespace

std::string render_gitlab(const LintReport& report, const std::filesystem::path& source_root) {
    ordered_json issues = ordered_json::array();
    report_detail::Fingerprints fingerprints;
    static const std::map<std::uint32_t, std::string> no_lines;
    auto add = [&](const Diagnostic& d, const std::map<std::uint32_t, std::string>& lines, bool execution_problem) {
        const std::string path = report_detail::repository_path(d.path, source_root);
        const bool blocker = execution_problem && d.severity == Severity::error;
        issues.push_back({{"description", d.message},
                          {"check_name", d.rule},
                          {"fingerprint", fingerprints.next(d, path, lines)},
                          {"severity", blocker ? std::string_view("blocker") : gitlab_severity(d.severity)},
                          {"location", {{"path", path}, {"lines", {{"begin", std::max<std::uint32_t>(d.pos.line, 1)}}}}}});
    };
    for (const auto& d : report.config_diagnostics) add(d, no_lines, true);
    for (const auto& file : report.files)
        for (const auto& d : file.diagnostics) add(d, file.quoted_lines, report_detail::is_execution_problem(file, d));
    return issues.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) + "\n";
}

}  // namespace esi
