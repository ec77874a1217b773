#include "esi/report/sarif.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "esi/check/registry.hpp"
#include "report/finding_identity.hpp"

namespace esi {

namespace {

namespace fs = std::filesystem;
using ordered_json = nlohmann::ordered_json;

constexpr std::string_view source_root_id = "%SRCROOT%";

std::string_view sarif_level(Severity s) {
    switch (s) {
        case Severity::error: return "error";
        case Severity::warning: return "warning";
        case Severity::info: return "note";
    }
    return "warning";
}

// A path as a URI reference (RFC 3986): percent-encode what is not unreserved.
std::string percent_encoded(const std::string& path) {
    std::string out;
    for (unsigned char c : path) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') out.push_back(static_cast<char>(c));
        else out += fmt::format("%{:02X}", c);
    }
    return out;
}

std::string file_uri(const fs::path& absolute) { return "file://" + percent_encoded(absolute.generic_string()); }

// The artifactLocation of a diagnostic's path: relative to %SRCROOT% when inside it.
class Locator {
public:
    explicit Locator(fs::path root) : root_(std::move(root).lexically_normal()) {}

    [[nodiscard]] std::string path(const std::string& path) const { return report_detail::repository_path(path, root_); }

    [[nodiscard]] ordered_json artifact(const std::string& original) const {
        const std::string in_repository = path(original);
        if (in_repository.empty() || in_repository.front() == '<') return {{"uri", percent_encoded(in_repository)}};  // <stdin>
        if (in_repository.front() == '/') return {{"uri", file_uri(in_repository)}};
        return {{"uri", percent_encoded(in_repository)}, {"uriBaseId", source_root_id}};
    }

    [[nodiscard]] ordered_json base_ids() const {
        std::string uri = file_uri(root_);
        if (uri.back() != '/') uri += '/';  // a base URI names a directory (SARIF 2.1.0 §3.14.14)
        return {{source_root_id, {{"uri", uri}}}};
    }

private:
    fs::path root_;
};

ordered_json physical_location(const Locator& locator, const std::string& path, SourcePos pos) {
    ordered_json physical{{"artifactLocation", locator.artifact(path)}};
    if (pos.known()) physical["region"] = {{"startLine", pos.line}, {"startColumn", std::max<std::uint32_t>(pos.column, 1)}};
    return physical;
}

// The fix's edits as SARIF replacements; none when a position is unknown (a fix the linter did
// not place, which no report of a lint run holds).
std::optional<ordered_json> sarif_replacements(const FileReport& file, const Fix& fix) {
    ordered_json replacements = ordered_json::array();
    for (const TextEdit& e : fix.edits) {
        const auto start = file.fix_positions.find(e.offset);
        const auto end = file.fix_positions.find(e.offset + e.length);
        if (start == file.fix_positions.end() || end == file.fix_positions.end()) return std::nullopt;
        ordered_json replacement{{"deletedRegion",
                                  {{"startLine", start->second.line},
                                   {"startColumn", start->second.column},
                                   {"endLine", end->second.line},
                                   {"endColumn", end->second.column}}}};
        if (!e.replacement.empty()) replacement["insertedContent"] = {{"text", e.replacement}};
        replacements.push_back(std::move(replacement));
    }
    if (replacements.empty()) return std::nullopt;
    return replacements;
}

// A safe fix as SARIF 2.1.0 §3.55: one artifactChange of the result's file, a replacement per
// edit; its deletedRegion in the run's columnKind (code points, as every region here), empty
// (start = end) for an insertion.
ordered_json sarif_fix(const Locator& locator, const std::string& path, const Fix& fix, ordered_json replacements) {
    return {{"description", {{"text", fix.description}}},
            {"artifactChanges",
             ordered_json::array({{{"artifactLocation", locator.artifact(path)}, {"replacements", std::move(replacements)}}})}};
}

}  // namespace

std::string render_sarif(const LintReport& report, const SarifOptions& options) {
    const Locator locator(options.source_root);
    ordered_json rules = ordered_json::array();
    std::map<std::string, std::size_t, std::less<>> rule_index;
    for (const Rule& r : all_rules()) {
        rule_index.emplace(std::string(r.id), rules.size());
        ordered_json rule{{"id", r.id},
                          {"shortDescription", {{"text", r.summary}}},
                          {"fullDescription", {{"text", r.rationale}}},
                          {"defaultConfiguration", {{"level", sarif_level(r.default_severity)}}}};
        // docs/rules.md has a "## <rule id>" heading per rule; the ids are lower-case kebab, so the
        // heading's anchor is the id itself.
        if (!options.rules_url.empty()) rule["helpUri"] = options.rules_url + "#" + std::string(r.id);
        rule["help"] = {{"text", fmt::format("{}\n\nBad:\n{}\n\nGood:\n{}", r.rationale, r.bad_example, r.good_example)}};
        rules.push_back(std::move(rule));
    }

    ordered_json notifications = ordered_json::array();
    auto notify = [&](const Diagnostic& d) {
        ordered_json n{{"level", sarif_level(d.severity)},
                       {"message", {{"text", d.message}}},
                       {"locations", ordered_json::array({{{"physicalLocation", physical_location(locator, d.path, d.pos)}}})},
                       {"descriptor", {{"id", d.rule}}}};
        notifications.push_back(std::move(n));
    };
    for (const auto& d : report.config_diagnostics) notify(d);
    for (const auto& file : report.files)
        if (!file.skipped.empty()) notify(Diagnostic{Severity::info, "skipped", "skipped: " + file.skipped, file.path, {}, {}, {}});

    ordered_json results = ordered_json::array();
    report_detail::Fingerprints fingerprints;
    for (const auto& file : report.files) {
        for (const auto& d : file.diagnostics) {
            if (report_detail::is_execution_problem(file, d)) {
                notify(d);
                continue;
            }
            ordered_json result{{"ruleId", d.rule}};
            if (auto it = rule_index.find(d.rule); it != rule_index.end()) result["ruleIndex"] = it->second;
            result["level"] = sarif_level(d.severity);
            result["message"] = {{"text", d.message}};
            result["locations"] = ordered_json::array({{{"physicalLocation", physical_location(locator, d.path, d.pos)}}});
            if (!d.notes.empty()) {
                ordered_json related = ordered_json::array();
                int id = 0;
                for (const auto& n : d.notes)
                    related.push_back({{"id", id++},
                                       {"physicalLocation", physical_location(locator, n.path, n.pos)},
                                       {"message", {{"text", n.message}}}});
                result["relatedLocations"] = std::move(related);
            }
            if (d.fix)
                if (std::optional<ordered_json> replacements = sarif_replacements(file, *d.fix))
                    result["fixes"] = ordered_json::array({sarif_fix(locator, d.path, *d.fix, std::move(*replacements))});
            result["partialFingerprints"] = {
                {sarif_fingerprint_key, fingerprints.next(d, locator.path(d.path), file.quoted_lines)}};
            results.push_back(std::move(result));
        }
    }

    const bool successful = std::none_of(notifications.begin(), notifications.end(),
                                         [](const ordered_json& n) { return n["level"] == "error"; });
    ordered_json invocation{{"executionSuccessful", successful}};
    if (!notifications.empty()) invocation["toolExecutionNotifications"] = std::move(notifications);
    ordered_json driver{{"name", "esi-lint"}, {"version", options.tool_version}};
    if (!options.rules_url.empty()) driver["informationUri"] = options.rules_url;
    driver["rules"] = std::move(rules);
    ordered_json root{{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
                      {"version", "2.1.0"},
                      {"runs", ordered_json::array({{{"tool", {{"driver", std::move(driver)}}},
                                                     {"invocations", ordered_json::array({std::move(invocation)})},
                                                     {"originalUriBaseIds", locator.base_ids()},
                                                     {"columnKind", "unicodeCodePoints"},
                                                     {"results", std::move(results)}}})}};
    return root.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) + "\n";
}

}  // namespace esi
