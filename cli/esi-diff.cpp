// esi-diff: semantic diff between two ESI files (revisions of one catalogue).
// Exit codes: 0 no change at or above --fail-on, 1 there is one, 2 usage error or unreadable input.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

#include "cli_common.hpp"
#include "diagnostic_line.hpp"
#include "out_of_memory.hpp"
#include "esi/device_selector.hpp"
#include "esi/diff/diff.hpp"
#include "esi/diff/filter.hpp"
#include "esi/diff/report.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/doc/diff_html.hpp"
#include "esi/io/read_file.hpp"
#include "esi/version.hpp"

namespace {

using esi::cli::exit_findings;
using esi::cli::exit_ok;
using esi::cli::exit_usage;

// A path inside the current directory as a relative one (what the user would type); any other
// path, and standard input, as given.
std::string shown_path(const std::string& path) {
    if (path.empty() || path == "<stdin>") return path;
    std::error_code ec;
    const std::filesystem::path cwd = std::filesystem::current_path(ec);
    if (ec) return path;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec).lexically_normal();
    if (ec) return path;
    const std::filesystem::path relative = absolute.lexically_relative(cwd);
    if (relative.empty() || *relative.begin() == "..") return path;
    return relative.generic_string();
}

bool reaches(esi::Verdict verdict, const std::string& fail_on) {
    if (fail_on == "never") return false;
    if (fail_on == "any") return verdict != esi::Verdict::identical;
    return verdict == esi::Verdict::breaking;
}

}  // namespace

namespace {

int run_tool(int argc, char** argv) {
    esi::cli::exit_with_code_two_when_out_of_memory("esi-diff");
    CLI::App app{"esi-diff: compare two EtherCAT ESI files semantically and classify every change"};
    std::string old_path;
    std::string new_path;
    std::string format = "text";
    std::string fail_on = "breaking";
    std::string device;
    app.add_option("OLD", old_path, "the old ESI file or YAML device source, or - for standard input (git show REV:dev.xml | esi-diff - dev.xml)")
        ->required();
    app.add_option("NEW", new_path, "the new ESI file or YAML device source, or - for standard input")->required();
    app.add_option("--format", format, "report format: text, json, markdown or html")
        ->check(CLI::IsMember({"text", "json", "markdown", "html"}));
    app.add_option("--fail-on", fail_on, "lowest class that makes the exit code 1: breaking, any or never")
        ->check(CLI::IsMember({"breaking", "any", "never"}));
    std::vector<std::string> ignore, only;
    app.add_option("--ignore", ignore, "leave out changes of these classes: cosmetic, compatible, breaking (comma-separated)")
        ->delimiter(',')
        ->check(CLI::IsMember({"cosmetic", "compatible", "breaking"}));
    app.add_option("--only", only, "report only changes of these classes: cosmetic, compatible, breaking (comma-separated)")
        ->delimiter(',')
        ->check(CLI::IsMember({"cosmetic", "compatible", "breaking"}))
        ->excludes("--ignore");
    esi::cli::add_device_option(app, device, "compare only this device");
    esi::cli::add_version_flag(app, "esi-diff");
    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;

    esi::DiffOptions options;
    if (!esi::cli::parse_device_option("esi-diff", device, options.device)) return exit_usage;
    options.keep_documents = format == "html";  // the HTML report draws both files

    if (old_path == "-" && new_path == "-") {
        std::cerr << "esi-diff: only one of OLD and NEW can be - (standard input)\n";
        return exit_usage;
    }
    esi::DiffSource old_source{old_path, std::nullopt};
    esi::DiffSource new_source{new_path, std::nullopt};
    for (esi::DiffSource* source : {&old_source, &new_source}) {
        if (source->path != "-") continue;
        source->path = "<stdin>";
        std::string error;
        source->bytes = esi::read_stdin_bytes(error);
        if (!source->bytes) {
            std::cerr << "esi-diff: <stdin>: cannot read: " << error << "\n";
            return exit_usage;
        }
    }
    esi::FileDiff diff = esi::diff_sources(std::move(old_source), std::move(new_source), options);
    if (!diff.result) {
        for (const auto& d : diff.diagnostics) print_diagnostic(d, "");
        if (diff.diagnostics.empty()) std::cerr << "esi-diff: could not read the input files\n";
        return exit_usage;
    }
    esi::DiffResult& result = *diff.result;
    if (!ignore.empty() || !only.empty()) {
        std::set<esi::ChangeClass> kept;
        if (only.empty()) kept = {esi::ChangeClass::cosmetic, esi::ChangeClass::compatible, esi::ChangeClass::breaking};
        for (const auto& name : only) kept.insert(*esi::change_class_named(name));
        for (const auto& name : ignore) kept.erase(*esi::change_class_named(name));
        esi::keep_classes(result, kept);
    }
    if (options.device && result.old_devices_compared == 0 && result.new_devices_compared == 0) {
        std::cerr << "esi-diff: --device " << device << " matches no device in either file\n";
        return exit_usage;
    }

    const esi::DiffLabels labels{shown_path(diff.old_path), shown_path(diff.new_path)};
    std::string report;
    if (format == "html") {
        esi::doc::DiffHtmlOptions html_options;
        html_options.template_dirs = esi::doc::template_search_path({}, esi::cli::executable_path(argc > 0 ? argv[0] : nullptr));
        esi::doc::DiffHtml html = esi::doc::render_diff_html(*diff.old_document, *diff.new_document, result, labels, html_options);
        for (const auto& d : html.diagnostics) print_diagnostic(d, "esi-diff");
        if (html.diagnostics.has_errors()) return exit_usage;
        report = std::move(html.html);
    } else if (format == "json")
        report = esi::render_diff_json(result);
    else if (format == "markdown")
        report = esi::render_diff_markdown(result, labels);
    else
        report = esi::render_diff_text(result, labels);
    esi::cli::write_stdout(report);
    return reaches(result.verdict, fail_on) ? exit_findings : exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return esi::cli::exit_with_stdout_checked("esi-diff", run_tool(argc, argv)); }
