#include "esi/lint/lint.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <thread>

#include "esi/check/run.hpp"
#include "lint/directory_walk.hpp"
#include "lint/file_queue.hpp"
#include "esi/lint/suppression.hpp"
#include "esi/lint/xsd.hpp"

namespace esi {

std::size_t LintReport::count(Severity severity) const {
    std::size_t n = config_diagnostics.count(severity);
    for (const auto& f : files) n += f.diagnostics.count(severity);
    return n;
}

bool LintReport::any_unreadable() const {
    return std::any_of(files.begin(), files.end(), [](const FileReport& f) { return f.unreadable; });
}

namespace {

// Applies the config to diagnostics that did not come from a rule's check (reader, schema).
void apply_settings(Diagnostics& diagnostics, const EffectiveConfig& config) {
    auto& items = diagnostics.items();
    std::vector<Diagnostic> kept;
    kept.reserve(items.size());
    for (auto& d : items) {
        const Rule* rule = find_rule(d.rule);
        if (!rule) {
            kept.push_back(std::move(d));
            continue;
        }
        // xml-syntax and encoding faults stay errors: there is no trustworthy document behind them.
        if (d.rule == "xml-syntax") {
            kept.push_back(std::move(d));
            continue;
        }
        const std::optional<Severity> severity = config.severity_of(d.rule, d.severity);
        if (!severity) continue;
        d.severity = *severity;
        kept.push_back(std::move(d));
    }
    items = std::move(kept);
}

FileReport lint_read_result(ReadResult read, const std::string& path, const EffectiveConfig& config, const SchemaSet* schemas) {
    FileReport report;
    report.path = path;
    Diagnostics diagnostics = std::move(read.diagnostics);
    for (const auto& d : diagnostics)
        if (d.rule == "io-error") report.unreadable = true;
    if (read.document) diagnostics.append(run_rules(*read.document, config));
    if (schemas && read.source && read.document) diagnostics.append(schemas->validate(*read.source));
    apply_settings(diagnostics, config);
    if (read.source) {
        const Suppressions suppressions = find_suppressions(*read.source, diagnostics);
        auto& items = diagnostics.items();
        items.erase(std::remove_if(items.begin(), items.end(), [&](const Diagnostic& d) { return suppressions.suppresses(d); }),
                    items.end());
    }
    diagnostics.sort();
    if (read.source) {
        for (const auto& d : diagnostics) {
            if (d.pos.known() && !report.quoted_lines.count(d.pos.line))
                report.quoted_lines.emplace(d.pos.line, std::string(read.source->line(d.pos.line)));
        }
    }
    report.diagnostics = std::move(diagnostics);
    return report;
}

}  // namespace

FileReport lint_bytes(std::string_view bytes, const std::string& path, const EffectiveConfig& config,
                      const std::optional<std::filesystem::path>& xsd_dir) {
    std::shared_ptr<SchemaSet> schemas;
    Diagnostics schema_diagnostics;
    if (xsd_dir) schemas = SchemaSet::load(*xsd_dir, schema_diagnostics);
    FileReport report = lint_read_result(read_esi(bytes, path), path, config, schemas.get());
    report.diagnostics.append(std::move(schema_diagnostics));
    report.diagnostics.sort();
    return report;
}

std::vector<std::filesystem::path> expand_inputs(const std::vector<std::filesystem::path>& inputs, Diagnostics& diagnostics) {
    std::vector<std::filesystem::path> files;
    for (const auto& input : inputs) {
        std::error_code ec;
        if (std::filesystem::is_directory(input, ec)) lint_detail::collect_xml_files(input, files, diagnostics);
        else if (std::filesystem::exists(input, ec)) files.push_back(input);
        else diagnostics.emplace(Severity::error, "io-error", "no such file or directory", input.string(), {});
    }
    return files;
}

LintReport lint_paths(const std::vector<std::filesystem::path>& inputs, const LintOptions& options) {
    LintReport report;
    Diagnostics missing;
    const std::vector<std::filesystem::path> files = expand_inputs(inputs, missing);
    for (auto& d : missing) {
        FileReport unreadable;
        unreadable.path = d.path;
        unreadable.unreadable = true;
        unreadable.diagnostics.add(d);
        report.files.push_back(std::move(unreadable));
    }

    std::shared_ptr<SchemaSet> schemas;
    if (options.xsd_dir) schemas = SchemaSet::load(*options.xsd_dir, report.config_diagnostics);

    // Configs: either the one given, or the nearest .esi-lint.yaml of each file (loaded once).
    std::map<std::string, std::optional<LintConfig>> loaded;
    auto load = [&](const std::filesystem::path& config_path) -> const std::optional<LintConfig>& {
        const std::string key = config_path.string();
        auto it = loaded.find(key);
        if (it != loaded.end()) return it->second;
        ConfigResult result = load_lint_config(config_path);
        report.config_diagnostics.append(std::move(result.diagnostics));
        return loaded.emplace(key, std::move(result.config)).first->second;
    };
    static const LintConfig default_config{};
    std::vector<EffectiveConfig> configs(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::optional<std::filesystem::path> config_path = options.config_path;
        if (!config_path) config_path = find_config_for(files[i]);
        const LintConfig* config = &default_config;
        if (config_path) {
            if (const auto& c = load(*config_path)) config = &*c;
        }
        configs[i] = effective_config(*config, files[i]);
    }

    std::vector<FileReport> results(files.size());
    unsigned jobs = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
    jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(files.size(), 1)));
    std::vector<std::uintmax_t> sizes(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::error_code ec;
        const std::uintmax_t size = std::filesystem::file_size(files[i], ec);
        sizes[i] = ec ? 0 : size;
    }
    const std::uintmax_t budget = FileQueue::default_budget(sizes);
    FileQueue queue(std::move(sizes), budget);
    auto worker = [&](unsigned number) {
        while (const std::optional<std::size_t> i = queue.take(number)) {
            results[*i] = lint_read_result(read_esi_file(files[*i]), files[*i].string(), configs[*i], schemas.get());
            queue.done(*i);
        }
    };
    if (jobs <= 1) {
        worker(0);
    } else {
        std::vector<std::thread> threads;
        for (unsigned t = 0; t < jobs; ++t) threads.emplace_back(worker, t);
        for (auto& t : threads) t.join();
    }
    for (auto& r : results) report.files.push_back(std::move(r));
    report.config_diagnostics.sort();
    return report;
}

}  // namespace esi
