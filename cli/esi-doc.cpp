// esi-doc: an ESI file or YAML device source -> OUTDIR/index.html and one self-contained HTML
// page per device (tables and SVG bit-layout pictures), rendered from templates/doc/.
// Exit codes: 0 written, 1 rendering or writing failed (nothing written), 2 usage error or
// unusable input (nothing written).

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <optional>

#include "cli_common.hpp"
#include "diagnostic_line.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/load/document.hpp"

namespace {

namespace fs = std::filesystem;

using esi::cli::exit_ok;
using esi::cli::exit_usage;
constexpr int exit_failed = esi::cli::exit_findings;

void print(const esi::Diagnostics& diagnostics) {
    esi::Diagnostics sorted = diagnostics;
    sorted.sort();
    for (const auto& d : sorted) print_diagnostic(d, "esi-doc");
}

}  // namespace

namespace {

int run_tool(int argc, char** argv) {
    CLI::App app{"esi-doc: HTML datasheets with process-data bit-layout pictures from an ESI file or YAML device source"};
    std::string source, output_dir, device, lang = "en";
    std::vector<std::string> template_dirs;
    app.add_option("source", source, "ESI file (.xml) or YAML device source (.yaml/.yml)")->required();
    app.add_option("-o,--output", output_dir, "output directory (created when missing)")->required();
    esi::cli::add_device_option(app, device, "only the matching devices");
    app.add_option("--lang", lang, "language of names: en, de, fr … or a decimal LcId (default en; falls back to English, then the first)");
    app.add_option("--templates", template_dirs, "directory searched for page templates before the built-in ones (repeatable)");
    esi::cli::add_version_flag(app, "esi-doc");
    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;

    esi::doc::DatasheetOptions options;
    if (!esi::cli::parse_device_option("esi-doc", device, options.device)) return exit_usage;
    const std::optional<std::uint32_t> lcid = esi::doc::parse_language(lang);
    if (!lcid) {
        std::cerr << "esi-doc: --lang: '" << lang << "' is neither a language code (en, de, fr …) nor a decimal LcId\n";
        return exit_usage;
    }
    options.lcid = *lcid;
    std::vector<fs::path> user_dirs;
    if (!esi::cli::parse_template_dirs("esi-doc", template_dirs, user_dirs)) return exit_usage;
    options.template_dirs = esi::doc::template_search_path(user_dirs, esi::cli::executable_path(argc > 0 ? argv[0] : nullptr));

    const esi::LoadedDocument loaded = esi::load_document_file(source);
    print(loaded.diagnostics);
    if (!loaded.usable()) return exit_usage;

    const esi::doc::Datasheets pages = esi::doc::render_datasheets(*loaded.document, output_dir, options);
    print(pages.diagnostics);
    if (pages.diagnostics.has_errors()) {
        for (const auto& d : pages.diagnostics)
            if (d.rule == "doc-no-device") return exit_usage;
        return exit_failed;
    }
    const esi::Diagnostics written = esi::write_files_atomically(pages.files);
    print(written);
    return written.has_errors() ? exit_failed : exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return esi::cli::exit_with_stdout_checked("esi-doc", run_tool(argc, argv)); }
