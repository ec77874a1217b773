#include "esi/report/baseline.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "report/finding_identity.hpp"

namespace esi {

namespace {

using ordered_json = nlohmann::ordered_json;
constexpr std::string_view format_key = "esi-lint-baseline";
constexpr int format_version = 1;

// Calls f(file, diagnostic, path, fingerprint) for every finding, numbering identical ones the
// way SARIF does, so a baseline written from one run matches the SARIF of the next.
template <class F>
void for_each_finding(const LintReport& report, const std::filesystem::path& source_root, F&& f) {
    report_detail::Fingerprints fingerprints;
    for (const auto& file : report.files)
        for (const auto& d : file.diagnostics) {
            if (report_detail::is_execution_problem(file, d)) continue;
            const std::string path = report_detail::repository_path(d.path, source_root);
            f(file, d, path, fingerprints.next(d, path, file.quoted_lines));
        }
}

}  // namespace

std::string render_baseline(const LintReport& report, const std::filesystem::path& source_root) {
    ordered_json findings = ordered_json::array();
    for_each_finding(report, source_root, [&](const FileReport&, const Diagnostic& d, const std::string& path, std::string fingerprint) {
        findings.push_back({{"rule", d.rule}, {"path", path}, {"fingerprint", std::move(fingerprint)}, {"message", d.message}});
    });
    const ordered_json root{{format_key, format_version}, {"findings", std::move(findings)}};
    return root.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) + "\n";
}

std::optional<Baseline> parse_baseline(std::string_view text, std::string& error) {
    const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
    if (root.is_discarded()) {
        error = "not JSON";
        return std::nullopt;
    }
    if (!root.is_object() || !root.contains(format_key)) {
        error = "not an esi-lint baseline (no \"" + std::string(format_key) + "\" key; write one with --write-baseline)";
        return std::nullopt;
    }
    if (root[std::string(format_key)] != format_version) {
        error = "baseline format " + root[std::string(format_key)].dump() + " is not supported (this esi-lint writes " +
                std::to_string(format_version) + ")";
        return std::nullopt;
    }
    const auto findings = root.find("findings");
    if (findings == root.end() || !findings->is_array()) {
        error = "\"findings\" is not a list";
        return std::nullopt;
    }
    Baseline out;
    std::size_t index = 0;
    for (const auto& item : *findings) {
        const auto text_of = [&](const char* key) -> const std::string* {
            if (!item.is_object()) return nullptr;
            const auto it = item.find(key);
            return it != item.end() && it->is_string() ? &it->get_ref<const std::string&>() : nullptr;
        };
        const std::string* rule = text_of("rule");
        const std::string* path = text_of("path");
        const std::string* fingerprint = text_of("fingerprint");
        if (!rule || !path || !fingerprint) {
            error = "finding " + std::to_string(index) + " lacks one of rule, path and fingerprint";
            return std::nullopt;
        }
        out.findings.emplace(*rule, *path, *fingerprint);
        ++index;
    }
    return out;
}

void apply_baseline(LintReport& report, const Baseline& baseline, const std::filesystem::path& source_root) {
    // Decide on the whole report first: the fingerprints number identical findings in report order.
    std::set<const Diagnostic*> known;
    for_each_finding(report, source_root, [&](const FileReport&, const Diagnostic& d, const std::string& path, const std::string& fingerprint) {
        if (baseline.findings.count({d.rule, path, fingerprint})) known.insert(&d);
    });
    for (auto& file : report.files) {
        Diagnostics kept;
        for (auto& d : file.diagnostics.items()) {
            if (known.count(&d)) ++report.baselined;
            else kept.add(std::move(d));
        }
        file.diagnostics = std::move(kept);
    }
}

}  // namespace esi
