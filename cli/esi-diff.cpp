// esi-diff: semantic diff between two ESI files (revisions of one catalogue).
// Exit codes: 0 no change at or above --fail-on, 1 there is one, 2 usage error or unreadable input.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "diagnostic_line.hpp"
#include "out_of_memory.hpp"
#include "esi/device_selector.hpp"
#include "esi/diff/diff.hpp"
#include "esi/diff/output.hpp"
#include "esi/version.hpp"

namespace {

constexpr int exit_clean = 0;
constexpr int exit_changes = 1;
constexpr int exit_usage = 2;

bool reaches(esi::Verdict verdict, const std::string& fail_on) {
    if (fail_on == "never") return false;
    if (fail_on == "any") return verdict != esi::Verdict::identical;
    return verdict == esi::Verdict::breaking;
}

}  // namespace

int main(int argc, char** argv) {
    cli::exit_with_code_two_when_out_of_memory("esi-diff");
    CLI::App app{"esi-diff: compare two EtherCAT ESI files semantically and classify every change"};
    std::string old_path;
    std::string new_path;
    std::string format = "text";
    std::string fail_on = "breaking";
    std::string device;
    app.add_option("OLD", old_path, "the old ESI file")->required();
    app.add_option("NEW", new_path, "the new ESI file")->required();
    app.add_option("--format", format, "text, json or markdown")->check(CLI::IsMember({"text", "json", "markdown"}));
    app.add_option("--fail-on", fail_on, "lowest class that makes the exit code 1: breaking, any or never")
        ->check(CLI::IsMember({"breaking", "any", "never"}));
    app.add_option("--device", device, "compare only PRODUCTCODE[:REVISION] (decimal, #x… or 0x…)");
    app.set_version_flag("--version", std::string(esi::version()));
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return exit_usage;
    }

    esi::DiffOptions options;
    if (!device.empty()) {
        std::string error;
        options.device = esi::parse_device_selector(device, error);
        if (!options.device) {
            std::cerr << "esi-diff: --device: " << error << "\n";
            return exit_usage;
        }
    }

    const esi::FileDiff diff = esi::diff_files(old_path, new_path, options);
    if (!diff.result) {
        for (const auto& d : diff.diagnostics) print_diagnostic_line(d, "");
        if (diff.diagnostics.empty()) std::cerr << "esi-diff: could not read the input files\n";
        return exit_usage;
    }
    const esi::DiffResult& result = *diff.result;
    if (options.device && result.old_devices_compared == 0 && result.new_devices_compared == 0) {
        std::cerr << "esi-diff: --device " << device << " matches no device in either file\n";
        return exit_usage;
    }

    const esi::DiffLabels labels{old_path, new_path};
    std::string output;
    if (format == "json")
        output = esi::render_diff_json(result);
    else if (format == "markdown")
        output = esi::render_diff_markdown(result, labels);
    else
        output = esi::render_diff_text(result, labels);
    std::fwrite(output.data(), 1, output.size(), stdout);
    std::fflush(stdout);
    return reaches(result.verdict, fail_on) ? exit_changes : exit_clean;
}
