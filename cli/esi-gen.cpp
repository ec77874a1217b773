// esi-gen: one device source (YAML, or an existing ESI file) -> ESI XML, C++ object-dictionary
// header, C99 slave tables, SOES object list and process-image structs.
// Exit codes: 0 written, 1 generation or writing failed (nothing written), 2 usage error or the
// source has errors (nothing written).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "cli_common.hpp"
#include "diagnostic_line.hpp"
#include "out_of_memory.hpp"
#include "esi/codegen/generate.hpp"
#include "esi/codegen/template_lookup.hpp"
#include "esi/device_selector.hpp"
#include "esi/enforce/limits.hpp"
#include "esi/import/import.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/io/leftovers.hpp"
#include "esi/io/same_file.hpp"
#include "esi/load/document.hpp"
#include "esi/version.hpp"
#include "esi/xml/reader.hpp"

namespace {

namespace fs = std::filesystem;

using esi::cli::exit_ok;
using esi::cli::exit_usage;
constexpr int exit_failed = esi::cli::exit_findings;  // generation or writing failed, nothing written

void print(const esi::Diagnostics& diagnostics) {
    esi::Diagnostics sorted = diagnostics;
    sorted.sort();
    for (const auto& d : sorted) print_diagnostic(d, "esi-gen");
}

// --import ESI.xml -o SOURCE.yaml: an ESI file -> the YAML device source (docs/yaml-import.md).
int import_esi(const std::string& esi_path, const std::string& output, const std::optional<esi::DeviceSelector>& device) {
    if (const esi::Diagnostics same = esi::refuse_output_over_input(output, {esi_path}); same.has_errors()) {
        print(same);
        return exit_usage;
    }
    esi::ReadResult read = esi::read_esi_file(esi_path);
    print(read.diagnostics);
    if (!read.document || read.diagnostics.has_errors()) return exit_usage;
    esi::ImportOptions options;
    options.device = device;
    const esi::ImportResult imported = esi::import_device_source(*read.document, options);
    print(imported.diagnostics);
    if (!imported.yaml || imported.diagnostics.has_errors()) return exit_usage;
    const esi::Diagnostics written = esi::write_file_atomically(output, *imported.yaml);
    print(written);
    return written.has_errors() ? exit_failed : exit_ok;
}

}  // namespace

namespace {

int run_tool(int argc, char** argv) {
    esi::cli::exit_with_code_two_when_out_of_memory("esi-gen");
    esi::install_leftover_cleanup();
    CLI::App app{"esi-gen: generate ESI XML, C/C++ object dictionaries, slave tables and process-image structs from one device source"};
    std::string source, output_dir, dump_model, device, prefix, import_path, config;
    std::vector<std::string> only, template_dirs;
    bool list_outputs = false, list_kinds = false, strict_size = false, strict = false;
    app.add_option("source", source, "YAML device source (.yaml/.yml) or ESI file (.xml)");
    app.add_option("-o,--output", output_dir, "output directory (created when missing)");
    app.add_option("--only", only, "output kinds to generate, comma-separated (default: all; see --list-kinds)")->delimiter(',');
    app.add_option("--templates", template_dirs, "directory searched for templates before the built-in ones (repeatable)");
    app.add_option("--dump-model", dump_model, "print the JSON view the templates render from, and exit")->check(CLI::IsMember({"json"}));
    esi::cli::add_device_option(app, device, "only the matching devices");
    app.add_option("--import", import_path, "ESI file to turn into a YAML device source (written to -o, a file)");
    app.add_option("--prefix", prefix, "C symbol prefix (default: each device's c_name)");
    app.add_option("--config", config,
                   "an .esi-lint.yaml profile whose limits (with the source's own) every generated device must meet");
    app.add_flag("--list-outputs", list_outputs, "print the files a run would write, one per line, and exit");
    app.add_flag("--list-kinds", list_kinds, "print the output kinds and exit");
    app.add_flag("--strict-size", strict_size,
                 "sii: refuse an image larger than Eeprom/ByteSize instead of leaving out optional content until it fits");
    app.add_flag("--strict", strict,
                 "sii: refuse an image that switches the PDI off (no esc: and no Eeprom/ConfigData) instead of warning");
    esi::cli::add_version_flag(app, "esi-gen");
    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;

    if (list_kinds) {
        for (const auto& kind : esi::codegen::output_kinds()) std::cout << kind.name << "\t" << kind.summary << "\n";
        return exit_ok;
    }
    if (!import_path.empty()) {
        if (output_dir.empty() || !source.empty()) {
            std::cerr << "esi-gen: --import ESI.xml -o SOURCE.yaml [--device PRODUCTCODE[:REVISION]]\n";
            return exit_usage;
        }
        std::optional<esi::DeviceSelector> selector;
        if (!esi::cli::parse_device_option("esi-gen", device, selector)) return exit_usage;
        return import_esi(import_path, output_dir, selector);
    }
    if (source.empty()) {
        std::cerr << "esi-gen: no source given (--help for usage)\n";
        return exit_usage;
    }
    if (output_dir.empty() && dump_model.empty()) {
        std::cerr << "esi-gen: give an output directory with -o (or --dump-model json)\n";
        return exit_usage;
    }
    if (const esi::Diagnostics bad = esi::codegen::check_output_kinds(only); bad.has_errors()) {
        print(bad);
        return exit_usage;
    }
    esi::codegen::GenerateOptions options;
    options.output_dir = output_dir;
    options.only = only;
    options.sii_strict_size = strict_size;
    options.sii_strict = strict;
    if (!esi::cli::parse_device_option("esi-gen", device, options.view.device)) return exit_usage;
    if (!prefix.empty()) options.view.symbol_prefix = prefix;
    std::vector<fs::path> user_dirs;
    if (!esi::cli::parse_template_dirs("esi-gen", template_dirs, user_dirs)) return exit_usage;
    options.template_dirs = esi::codegen::template_search_path(user_dirs, esi::cli::executable_path(argc > 0 ? argv[0] : nullptr));

    esi::LoadedDocument loaded = esi::load_document_file(source);
    print(loaded.diagnostics);
    if (!loaded.document || loaded.diagnostics.has_errors()) return exit_usage;
    // A device that breaks its limits is a source error: nothing is generated from it.
    const esi::Diagnostics broken = esi::enforce_limits(
        loaded, {config.empty() ? std::nullopt : std::optional<fs::path>(config), options.view.device});
    print(broken);
    if (broken.has_errors()) return exit_usage;

    if (!dump_model.empty()) {
        esi::codegen::ModelViewText view = esi::codegen::model_view_json(*loaded.document, options.view);
        print(view.diagnostics);
        if (view.diagnostics.has_errors()) return exit_usage;
        std::fwrite(view.json.data(), 1, view.json.size(), stdout);
        return exit_ok;
    }
    // Planning first: a selection that matches no device or would overwrite the source is a usage
    // error, found before anything is rendered.
    esi::Diagnostics planning;
    const auto planned = esi::codegen::plan_outputs(*loaded.document, options, planning);
    print(planning);
    if (planning.has_errors()) return exit_usage;
    if (list_outputs) {
        for (const auto& file : planned) std::cout << file.path.generic_string() << "\n";
        return exit_ok;
    }

    esi::codegen::GenerateResult generated = esi::codegen::generate_outputs(*loaded.document, options);
    print(generated.diagnostics);
    if (generated.diagnostics.has_errors()) return exit_failed;
    const esi::Diagnostics written = esi::write_output_set(output_dir, generated.files);
    print(written);
    return written.has_errors() ? exit_failed : exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return esi::cli::exit_with_stdout_checked("esi-gen", run_tool(argc, argv)); }
