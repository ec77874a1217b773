#include "esi/report/statistics.hpp"

#include <algorithm>
#include <map>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "esi/check/registry.hpp"

namespace esi {

namespace {

struct Row {
    std::string rule;
    Severity severity;
    std::size_t count;
};

// Config problems are not counted: they stop the run or are the tool's own (an unusable schema).
std::vector<Row> rows_of(const LintReport& report) {
    std::map<std::pair<std::string, Severity>, std::size_t> counts;
    for (const auto& file : report.files)
        for (const auto& d : file.diagnostics) ++counts[{d.rule, d.severity}];
    std::vector<Row> rows;
    for (const auto& [key, count] : counts) rows.push_back({key.first, key.second, count});
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
        // most frequent first; then the more severe; then by id (the map's order)
        return std::tie(b.count, b.severity) < std::tie(a.count, a.severity);
    });
    return rows;
}

std::size_t linted_files(const LintReport& report) {
    return static_cast<std::size_t>(
        std::count_if(report.files.begin(), report.files.end(), [](const FileReport& f) { return f.skipped.empty(); }));
}

std::string_view summary_of(const std::string& rule) {
    const Rule* r = find_rule(rule);
    return r ? r->summary : std::string_view{};
}

}  // namespace

std::string render_statistics_text(const LintReport& report) {
    const std::vector<Row> rows = rows_of(report);
    std::size_t width = 0;
    for (const Row& r : rows) width = std::max(width, r.rule.size());
    std::string out;
    for (const Row& r : rows) {
        const std::string line = fmt::format("{:>6}  {:<7}  {:<{}}  {}", r.count, to_string(r.severity), r.rule, width, summary_of(r.rule));
        out.append(line.substr(0, line.find_last_not_of(' ') + 1)).push_back('\n');
    }
    std::size_t total = 0;
    for (const Row& r : rows) total += r.count;
    const std::size_t files = linted_files(report);
    out += fmt::format("{} finding{} in {} file{}", total, total == 1 ? "" : "s", files, files == 1 ? "" : "s");
    if (report.baselined) out += fmt::format(" ({} more in the baseline)", report.baselined);
    out += "\n";
    return out;
}

std::string render_statistics_json(const LintReport& report) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const Row& r : rows_of(report))
        rows.push_back({{"rule", r.rule}, {"severity", to_string(r.severity)}, {"count", r.count}, {"summary", summary_of(r.rule)}});
    const nlohmann::ordered_json root{{"statistics", std::move(rows)},
                                      {"summary",
                                       {{"files", linted_files(report)},
                                        {"errors", report.count(Severity::error)},
                                        {"warnings", report.count(Severity::warning)},
                                        {"infos", report.count(Severity::info)},
                                        {"baselined", report.baselined}}}};
    return root.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) + "\n";
}

}  // namespace esi
