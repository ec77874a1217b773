#include "esi/lint/lint.hpp"

#include <algorithm>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <map>
#include <mutex>
#include <thread>

#include "esi/check/run.hpp"
#include "esi/io/read_file.hpp"
#include "esi/load/document.hpp"
#include "esi/xml/foreign_root.hpp"
#include "esi/yaml/source.hpp"
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

// One input as the lint pipeline sees it: the document the front end built (ESI XML or a YAML
// device source), the front end's diagnostics and the text positions refer to.
struct LintInput {
    std::optional<EsiDocument> document;
    Diagnostics diagnostics;
    SourceTextPtr source;
    bool xml = true;  // the schema and the XML-only checks apply
};

LintInput from_xml(ReadResult read) {
    return LintInput{std::move(read.document), std::move(read.diagnostics), std::move(read.source), true};
}

LintInput from_yaml(DeviceSource source) {
    return LintInput{std::move(source.document), std::move(source.diagnostics), std::move(source.source), false};
}

bool has_yaml_extension(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".yaml" || ext == ".yml";
}

LintInput read_input_file(const std::filesystem::path& path) {
    // Named as a YAML source: read under the YAML front end's bounds (esi/yaml/source.hpp).
    if (has_yaml_extension(path)) return from_yaml(load_device_source_file(path));
    return from_xml(read_esi_file(path));
}

LintInput read_input_bytes(std::string_view bytes, const std::string& path) {
    if (document_format(bytes, path) == DocumentFormat::yaml_source) return from_yaml(load_device_source(bytes, path));
    return from_xml(read_esi(bytes, path));
}

LintInput read_input_bytes(std::string&& bytes, const std::string& path) {
    if (document_format(bytes, path) == DocumentFormat::yaml_source) return from_yaml(load_device_source(bytes, path));
    return from_xml(read_esi_owned(std::move(bytes), path));
}

FileReport lint_input(LintInput read, const std::string& path, const EffectiveConfig& config, const SchemaSet* schemas) {
    FileReport report;
    report.path = path;
    Diagnostics diagnostics = std::move(read.diagnostics);
    for (const auto& d : diagnostics)
        if (d.rule == "io-error") report.unreadable = true;
    if (read.document) diagnostics.append(run_rules(*read.document, config));
    // The fixes address XML text; a YAML source's positions are not that.
    if (!read.xml)
        for (auto& d : diagnostics.items()) d.fix.reset();
    if (schemas && read.xml && read.source && read.document) diagnostics.append(schemas->validate(*read.source));
    // The findings are made: the model goes before the lines they quote are read, so that a big
    // catalogue's model and its text (a mapped file whose pages the reader let go) are not both
    // in memory (docs/performance.md). The allocator keeps freed memory for later use; after a big
    // model it is given back to the system, so that the pages the quoting reads do not come on top.
    read.document.reset();
#if defined(__GLIBC__)
    if (read.source && read.source->text().size() >= map_from_bytes) ::malloc_trim(0);
#endif
    apply_settings(diagnostics, config);
    if (read.source) {
        const Suppressions suppressions = find_suppressions(*read.source, diagnostics);
        auto& items = diagnostics.items();
        items.erase(std::remove_if(items.begin(), items.end(), [&](const Diagnostic& d) { return suppressions.suppresses(d); }),
                    items.end());
    }
    diagnostics.sort();
    if (read.source)
        for (const auto& d : diagnostics)
            if (d.fix)
                for (const auto& e : d.fix->edits)
                    for (const std::size_t offset : {e.offset, e.offset + e.length})
                        report.fix_positions.emplace(offset, read.source->position_of(offset));
    if (read.source) {
        for (const auto& d : diagnostics) {
            if (d.pos.known() && !report.quoted_lines.count(d.pos.line))
                report.quoted_lines.emplace(d.pos.line, std::string(read.source->line(d.pos.line)));
        }
    }
    report.diagnostics = std::move(diagnostics);
    return report;
}

// A file a directory walk found that is well-formed XML of another kind (an ENI, a master's
// configuration): not linted, with the reason.
std::optional<std::string> foreign_file(const LintInput& read) {
    if (!read.xml || !read.document || read.document->kind != DocumentKind::unknown || !read.source) return std::nullopt;
    const std::optional<ForeignDocument> foreign = recognise_foreign_document(read.source->text());
    if (!foreign) return std::nullopt;
    return "not an ESI file (" + std::string(foreign->what) + ", root element <" + foreign->root + ">)";
}

}  // namespace

namespace {

template <class Bytes>
FileReport lint_input_bytes(Bytes&& bytes, const std::string& path, const EffectiveConfig& config,
                            const std::optional<std::filesystem::path>& xsd_dir) {
    std::shared_ptr<SchemaSet> schemas;
    Diagnostics schema_diagnostics;
    if (xsd_dir) schemas = SchemaSet::load(*xsd_dir, schema_diagnostics);
    FileReport report = lint_input(read_input_bytes(std::forward<Bytes>(bytes), path), path, config, schemas.get());
    report.diagnostics.append(std::move(schema_diagnostics));
    report.diagnostics.sort();
    return report;
}

}  // namespace

FileReport lint_bytes(std::string_view bytes, const std::string& path, const EffectiveConfig& config,
                      const std::optional<std::filesystem::path>& xsd_dir) {
    return lint_input_bytes(bytes, path, config, xsd_dir);
}

FileReport lint_bytes(std::string&& bytes, const std::string& path, const EffectiveConfig& config,
                      const std::optional<std::filesystem::path>& xsd_dir) {
    return lint_input_bytes(std::move(bytes), path, config, xsd_dir);
}

namespace {

struct Input {
    std::filesystem::path path;
    bool walked = false;  // found by a directory walk, not named
};

std::vector<Input> expand_marked(const std::vector<std::filesystem::path>& inputs, Diagnostics& diagnostics) {
    std::vector<Input> files;
    for (const auto& input : inputs) {
        std::error_code ec;
        if (std::filesystem::is_directory(input, ec)) {
            std::vector<std::filesystem::path> found;
            lint_detail::collect_xml_files(input, found, diagnostics);
            for (auto& f : found) files.push_back({std::move(f), true});
        } else if (std::filesystem::exists(input, ec)) {
            files.push_back({input, false});
        } else {
            diagnostics.emplace(Severity::error, "io-error", "no such file or directory", input.string(), {});
        }
    }
    return files;
}

}  // namespace

std::vector<std::filesystem::path> expand_inputs(const std::vector<std::filesystem::path>& inputs, Diagnostics& diagnostics) {
    std::vector<std::filesystem::path> files;
    for (auto& input : expand_marked(inputs, diagnostics)) files.push_back(std::move(input.path));
    return files;
}

LintReport lint_paths(const std::vector<std::filesystem::path>& inputs, const LintOptions& options) {
    LintReport report;
    Diagnostics missing;
    std::vector<Input> files = expand_marked(inputs, missing);
    for (auto& d : missing) {
        FileReport unreadable;
        unreadable.path = d.path;
        unreadable.unreadable = true;
        unreadable.diagnostics.add(d);
        report.files.push_back(std::move(unreadable));
    }

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
    std::error_code no_cwd;
    const std::filesystem::path cwd = std::filesystem::current_path(no_cwd);
    // The nearest config is looked for once per directory: the walk up the tree costs some
    // 28,000 instructions a file (an absolute path, a stat per level of the tree).
    std::map<std::string, std::optional<std::filesystem::path>> nearest_config;
    const auto find_nearest_config = [&](const std::filesystem::path& file) {
        const auto [it, added] = nearest_config.try_emplace(file.parent_path().native());
        if (added) it->second = find_config_for(file);
        return it->second;
    };
    std::vector<EffectiveConfig> configs;
    std::vector<Input> kept;
    for (auto& file : files) {
        std::optional<std::filesystem::path> config_path = options.config_path;
        if (!config_path) config_path = find_nearest_config(file.path);
        const LintConfig* config = &default_config;
        if (config_path) {
            if (const auto& c = load(*config_path)) config = &*c;
        }
        // Exclusion is for what a walk finds; a file named on the command line is linted (as ruff does).
        const auto excluded = [&](const ExcludeGlob& g) { return exclude_matches(g, file.path); };
        if (file.walked && (std::any_of(config->exclude.begin(), config->exclude.end(), excluded) ||
                            std::any_of(options.exclude.begin(), options.exclude.end(),
                                        [&](const std::string& glob) { return excluded(ExcludeGlob{cwd, glob}); }))) {
            ++report.excluded;
            continue;
        }
        configs.push_back(effective_config(*config, file.path));
        kept.push_back(std::move(file));
    }
    files = std::move(kept);
    if (options.config_path && loaded.empty()) load(*options.config_path);  // checked even with no file to lint
    if (report.config_diagnostics.has_errors()) {
        // Linting under defaults would report what the user switched off and miss their limits.
        report.stopped_by_config = true;
        report.config_diagnostics.sort();
        return report;
    }

    std::shared_ptr<SchemaSet> schemas;
    if (options.xsd_dir) schemas = SchemaSet::load(*options.xsd_dir, report.config_diagnostics);

    std::vector<FileReport> results(files.size());
    unsigned jobs = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
    jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(files.size(), 1)));
    std::vector<std::uintmax_t> sizes(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::error_code ec;
        const std::uintmax_t size = std::filesystem::file_size(files[i].path, ec);
        sizes[i] = ec ? 0 : size;
    }
    const std::uintmax_t budget = FileQueue::default_budget(sizes);
    FileQueue queue(std::move(sizes), budget);
    auto worker = [&](unsigned number) {
        while (const std::optional<std::size_t> i = queue.take(number)) {
            const Input& file = files[*i];
            LintInput input = read_input_file(file.path);
            std::optional<std::string> foreign = file.walked ? foreign_file(input) : std::nullopt;
            if (foreign) {
                results[*i].path = file.path.string();
                results[*i].skipped = std::move(*foreign);
            } else {
                results[*i] = lint_input(std::move(input), file.path.string(), configs[*i], schemas.get());
            }
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
