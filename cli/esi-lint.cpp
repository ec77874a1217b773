// esi-lint: checks ESI files against the ETG rules and the vendor's own limits.
// Exit codes: 0 nothing reaches --fail-on, 1 something does, 2 usage error or unreadable input.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <unistd.h>

#include "cli_common.hpp"
#include "color_option.hpp"
#include "esi/check/registry.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/io/read_file.hpp"
#include "esi/lint/fix.hpp"
#include "esi/lint/lint.hpp"
#include "esi/report/baseline.hpp"
#include "esi/report/gitlab.hpp"
#include "esi/report/lint_output.hpp"
#include "esi/report/sarif.hpp"
#include "esi/report/statistics.hpp"
#include "esi/version.hpp"
#include "out_of_memory.hpp"

namespace {

using esi::cli::exit_findings;
using esi::cli::exit_ok;
using esi::cli::exit_usage;

bool reaches(esi::Severity severity, const std::string& fail_on) {
    if (fail_on == "never") return false;
    if (fail_on == "info") return true;
    if (fail_on == "warning") return severity != esi::Severity::info;
    return severity == esi::Severity::error;
}

// --fix and --diff on the files whose findings have fixes. --diff prints the diffs and gives the
// exit code (1 when there is something to fix, as ruff does); --fix writes the files, reports what
// it did on stderr and returns nullopt so that the files are linted again.
std::optional<int> fix_files(const esi::LintReport& report, const esi::LintOptions& options, bool show_diff) {
    std::size_t fixed_files = 0;
    std::size_t fixed_findings = 0;
    bool failed = false;
    std::string diffs;
    for (const auto& file : report.files) {
        const bool fixable = std::any_of(file.diagnostics.begin(), file.diagnostics.end(), [](const esi::Diagnostic& d) { return d.fix.has_value(); });
        if (!fixable) continue;
        const esi::FixedText fixed = esi::fix_file(file.path, options);
        if (!fixed.refused.empty()) {
            std::cerr << file.path << ": note: not fixed: " << fixed.refused << "\n";
            continue;
        }
        if (fixed.applied == 0) continue;
        if (show_diff) {
            diffs += esi::unified_diff(fixed.original, fixed.edits, file.path);
        } else {
            const esi::Diagnostics written = esi::write_fixed_file(file.path, fixed);
            for (const auto& d : written) std::cerr << esi::format_diagnostic(d);
            if (written.has_errors()) {
                failed = true;
                continue;
            }
        }
        ++fixed_files;
        fixed_findings += fixed.applied;
    }
    if (show_diff) {
        esi::cli::write_stdout(diffs);
        std::cerr << "esi-lint: " << fixed_findings << " fixable finding" << (fixed_findings == 1 ? "" : "s") << " in " << fixed_files
                  << " file" << (fixed_files == 1 ? "" : "s") << "\n";
        return failed ? exit_usage : fixed_findings ? exit_findings : exit_ok;
    }
    std::cerr << "esi-lint: fixed " << fixed_findings << " finding" << (fixed_findings == 1 ? "" : "s") << " in " << fixed_files << " file"
              << (fixed_files == 1 ? "" : "s") << "\n";
    if (failed) return exit_usage;
    return std::nullopt;
}

// --fix - and --diff -: standard input in, the fixed file (or the diff) on standard output, as a
// filter in an editor or a pipe. Standard output is the file, so what was fixed, what could not
// be and the findings left go to standard error; the exit code is that of the findings left
// (--fix) or 1 when there is something to fix (--diff).
int fix_stdin(const esi::LintOptions& options, bool show_diff, const std::string& fail_on) {
    std::string error;
    const std::optional<std::string> bytes = esi::read_stdin_bytes(error);
    if (!bytes) {
        std::cerr << "<stdin>: error: cannot read: " << error << " [io-error]\n";
        return exit_usage;
    }
    esi::EffectiveConfig config;
    std::optional<std::filesystem::path> config_path = options.config_path;
    if (!config_path) config_path = esi::find_config_for(std::filesystem::current_path() / "stdin.xml");
    if (config_path) {
        const esi::ConfigResult loaded = esi::load_lint_config(*config_path);
        for (const auto& d : loaded.diagnostics) std::cerr << esi::format_diagnostic(d);
        if (!loaded.config) return exit_usage;
        config = esi::effective_config(*loaded.config, "stdin.xml");
    }
    const esi::FixedText fixed = esi::apply_fixes(*bytes, "<stdin>", config);
    if (!fixed.refused.empty()) std::cerr << "<stdin>: note: not fixed: " << fixed.refused << "\n";
    const char* plural = fixed.applied == 1 ? "" : "s";
    if (show_diff) {
        if (fixed.applied) esi::cli::write_stdout(esi::unified_diff(fixed.original, fixed.edits, "<stdin>"));
        std::cerr << "esi-lint: " << fixed.applied << " fixable finding" << plural << " in <stdin>\n";
        return fixed.applied ? exit_findings : exit_ok;
    }
    esi::cli::write_stdout(fixed.bytes);
    std::cerr << "esi-lint: fixed " << fixed.applied << " finding" << plural << " in <stdin>\n";
    const esi::FileReport left = esi::lint_bytes(fixed.bytes, "<stdin>", config, options.xsd_dir);
    int code = exit_ok;
    for (const auto& d : left.diagnostics) {
        std::cerr << esi::format_diagnostic(d);
        if (d.rule == "io-error") code = exit_usage;
        else if (code == exit_ok && reaches(d.severity, fail_on)) code = exit_findings;
    }
    return code;
}

}  // namespace

namespace {

int run_tool(int argc, char** argv) {
    esi::cli::exit_with_code_two_when_out_of_memory("esi-lint");
    CLI::App app{"esi-lint: check EtherCAT ESI files against ETG rules and vendor limits"};
    std::vector<std::string> paths;
    std::string format = "text";
    std::string fail_on = "error";
    std::string config;
    std::string xsd;
    std::string explain;
    bool list_rules = false;
    bool no_source = false;
    bool statistics = false;
    bool fix = false;
    bool show_diff = false;
    std::vector<std::string> exclude;
    std::string baseline_path;
    std::string write_baseline_path;
    std::string color;
    unsigned jobs = 0;
    app.add_option("paths", paths,
                   "ESI files, YAML device sources (*.yaml, *.yml), directories (recursive *.xml; hidden folders and CMake "
                   "build trees skipped) or - for stdin");
    std::string sarif_help_base;
    app.add_option("--format", format,
                   "text, json, sarif, github (workflow annotations) or gitlab (Code Quality report); with --list-rules: text, "
                   "json or markdown")
        ->check(CLI::IsMember({"text", "json", "sarif", "github", "gitlab", "markdown"}));
    app.add_option("--sarif-help-base", sarif_help_base,
                   "sarif: the published address of docs/rules.md; each rule's helpUri is URL#rule-id")
        ->type_name("URL");
    app.add_option("--fail-on", fail_on, "lowest severity that makes the exit code 1")
        ->check(CLI::IsMember({"error", "warning", "info", "never"}));
    app.add_option("--config", config, "config file (default: nearest .esi-lint.yaml upwards from each file)");
    app.add_option("--xsd", xsd, "also validate against the ETG schema files in this directory");
    app.add_flag("--list-rules", list_rules, "print the rule catalogue");
    app.add_option("--explain", explain, "print one rule's rationale with a bad and a good example");
    app.add_option("-j,--jobs", jobs, "files linted in parallel (default: all cores)");
    app.add_flag("--no-source", no_source, "text format: do not quote the source line");
    app.add_option("--exclude", exclude,
                   "glob of files a directory walk does not lint (relative to the current directory; repeatable; added to "
                   "the config's exclude:)")
        ->type_name("GLOB")
        ->allow_extra_args(false);  // one glob per --exclude: the paths follow
    app.add_option("--baseline", baseline_path, "do not report or count the findings this baseline file holds")->type_name("FILE");
    app.add_option("--write-baseline", write_baseline_path, "write every finding of this run to a baseline file")
        ->type_name("FILE");
    app.add_flag("--statistics", statistics, "print the number of findings per rule and severity instead of the findings");
    app.add_flag("--fix", fix, "apply the safe fixes (rules marked [*] in --list-rules) to the files, then report what is left; with - alone, "
                 "write the fixed standard input to standard output and the findings left to standard error");
    app.add_flag("--diff", show_diff, "print the safe fixes as a unified diff instead of applying them");
    esi::cli::add_color_option(app, color, "text format output");
    esi::cli::add_version_flag(app, "esi-lint");
    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;

    if (list_rules) {
        std::cout << (format == "json"       ? esi::render_rule_list_json()
                       : format == "markdown" ? esi::render_rule_list_markdown()
                                              : esi::render_rule_list_text());
        return exit_ok;
    }
    if (format == "markdown") {
        std::cerr << "esi-lint: --format markdown is only for --list-rules\n";
        return exit_usage;
    }
    if (!explain.empty()) {
        const std::string text = esi::render_rule_explanation(explain);
        if (text.empty()) {
            const std::string_view nearest = esi::nearest_rule_id(explain);
            std::cerr << "esi-lint: unknown rule '" << explain << "'"
                      << (nearest.empty() ? "" : "; did you mean '" + std::string(nearest) + "'?") << " (see --list-rules)\n";
            return exit_usage;
        }
        std::cout << text;
        return exit_ok;
    }
    if (paths.empty()) {
        std::cerr << "esi-lint: no input files (give files, directories or - for stdin; --help for usage)\n";
        return exit_usage;
    }

    if (statistics && format != "text" && format != "json") {
        std::cerr << "esi-lint: --statistics prints text or json\n";
        return exit_usage;
    }
    const bool fix_stdin_only = (fix || show_diff) && std::find(paths.begin(), paths.end(), "-") != paths.end();
    if (fix_stdin_only && paths.size() > 1) {
        // Standard output carries the one fixed input; files beside it would have nowhere to go.
        std::cerr << "esi-lint: --fix - and --diff - take standard input alone, no other path\n";
        return exit_usage;
    }
    std::optional<esi::Baseline> baseline;
    if (!baseline_path.empty()) {
        std::string error;
        const std::optional<std::string> text = esi::read_file_bytes(baseline_path, error);
        if (text) baseline = esi::parse_baseline(*text, error);
        if (!baseline) {
            std::cerr << "esi-lint: --baseline " << baseline_path << ": " << error << "\n";
            return exit_usage;
        }
    }

    esi::LintOptions options;
    if (!config.empty()) options.config_path = config;
    if (!xsd.empty()) options.xsd_dir = xsd;
    options.jobs = jobs;
    options.exclude = exclude;

    if (fix_stdin_only) return fix_stdin(options, show_diff, fail_on);

    esi::LintReport report;
    std::vector<std::filesystem::path> files;
    bool use_stdin = false;
    for (const auto& p : paths) {
        if (p == "-") use_stdin = true;
        else files.emplace_back(p);
    }
    if (!files.empty()) report = esi::lint_paths(files, options);
    if ((fix || show_diff) && !report.stopped_by_config) {
        const std::optional<int> code = fix_files(report, options, show_diff);
        if (code) return *code;  // --diff: the diff is the output
        report = esi::lint_paths(files, options);  // what is left after fixing
    }
    std::optional<std::string> bytes;
    if (use_stdin) {
        std::string error;
        bytes = esi::read_stdin_bytes(error);
        if (!bytes) {
            esi::FileReport unreadable;
            unreadable.path = "<stdin>";
            unreadable.unreadable = true;
            unreadable.diagnostics.emplace(esi::Severity::error, "io-error", "cannot read: " + error, "<stdin>", {});
            report.files.push_back(std::move(unreadable));
        }
    }
    if (bytes) {
        std::optional<std::filesystem::path> config_path = options.config_path;
        if (!config_path) config_path = esi::find_config_for(std::filesystem::current_path() / "stdin.xml");
        esi::EffectiveConfig effective;
        if (config_path && !report.stopped_by_config) {
            esi::ConfigResult loaded = esi::load_lint_config(*config_path);
            report.config_diagnostics.append(std::move(loaded.diagnostics));
            if (loaded.config) effective = esi::effective_config(*loaded.config, "stdin.xml");
            else report.stopped_by_config = true;
        }
        if (!report.stopped_by_config) report.files.push_back(esi::lint_bytes(*bytes, "<stdin>", effective, options.xsd_dir));
    }

    std::error_code no_cwd;
    const std::filesystem::path source_root = std::filesystem::current_path(no_cwd);  // the checkout root in CI
    if (!write_baseline_path.empty() && !report.stopped_by_config) {
        const std::string text = esi::render_baseline(report, source_root);
        const esi::Diagnostics written = esi::write_file_atomically(write_baseline_path, text);
        for (const auto& d : written) std::cerr << esi::format_diagnostic(d);
        if (written.has_errors()) return exit_usage;
        // What was just written is the baseline of this run: the report shows what it left out.
        std::string ignored;
        baseline = esi::parse_baseline(text, ignored);
    }
    if (baseline) esi::apply_baseline(report, *baseline, source_root);

    std::string output;
    if (statistics) output = format == "json" ? esi::render_statistics_json(report) : esi::render_statistics_text(report);
    else if (format == "json") output = esi::render_json(report);
    else if (format == "sarif")
        output = esi::render_sarif(report, {.tool_version = std::string(esi::version()),
                                            .source_root = source_root,
                                            .rules_url = sarif_help_base});
    else if (format == "gitlab") output = esi::render_gitlab(report, source_root);
    else if (format == "github") output = esi::render_github(report);
    else output = esi::render_text(report, {.show_source = !no_source, .color = esi::cli::color_enabled(color, STDOUT_FILENO)});
    esi::cli::write_stdout(output);

    if (report.any_unreadable() || report.config_diagnostics.has_errors() || report.stopped_by_config) return exit_usage;
    for (const auto& file : report.files)
        for (const auto& d : file.diagnostics)
            if (reaches(d.severity, fail_on)) return exit_findings;
    return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return esi::cli::exit_with_stdout_checked("esi-lint", run_tool(argc, argv)); }
