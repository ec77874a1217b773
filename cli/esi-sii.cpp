// esi-sii: SII EEPROM images. `build` writes the image of an ESI (or YAML) device, `dump`
// decodes an image and reports every fault with its byte offset, `check` compares an image
// with its ESI device as the ETG conformance tool does.
// Exit codes: 0 all well, 1 dump found a fault / check found a mismatch, 2 usage error or
// unreadable/unusable input.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>

#include "cli_common.hpp"
#include "esi/device_selector.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/io/leftovers.hpp"
#include "esi/io/same_file.hpp"
#include "esi/load/document.hpp"
#include "esi/sii/build.hpp"
#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/image_file.hpp"
#include "esi/sii/render.hpp"
#include "esi/version.hpp"
#include "out_of_memory.hpp"

namespace {

using esi::cli::exit_findings;
using esi::cli::exit_ok;
using esi::cli::exit_usage;

void print(std::FILE* stream, const std::string& text) {
    std::fwrite(text.data(), 1, text.size(), stream);
    std::fflush(stream);
}

// The document of an ESI or YAML input; nullopt (after printing why) when unusable.
std::optional<esi::EsiDocument> load_document(const std::string& input) {
    esi::LoadedDocument loaded = esi::load_document_file(input);
    esi::Diagnostics errors;
    for (const auto& d : loaded.diagnostics)
        if (d.severity == esi::Severity::error) errors.add(d);
    print(stderr, esi::sii::render_diagnostics_text(errors));
    if (!loaded.usable()) {
        print(stderr, fmt::format("esi-sii: {}: cannot use this input\n", input));
        return std::nullopt;
    }
    return std::move(loaded.document);
}

std::string device_label(const esi::Device& d) {
    return fmt::format("{} (product code 0x{:08X}, revision 0x{:08X})", d.type.text, d.type.product_code.value_or(0),
                       d.type.revision_no.value_or(0));
}

std::string device_list(const std::vector<const esi::Device*>& devices) {
    std::string out;
    for (const auto* d : devices)
        out += fmt::format("  --device 0x{:08X}:0x{:08X}  {}\n", d->type.product_code.value_or(0), d->type.revision_no.value_or(0),
                           d->type.text);
    return out;
}

int run_build(const std::string& input, const std::string& output, const std::string& device_text, const std::string& format_text,
              const esi::sii::BuildOptions& options) {
    esi::sii::ImageFormat format{};
    if (!esi::sii::parse_image_format(format_text, format)) {
        print(stderr, fmt::format("esi-sii build: --format must be bin, hex or c (not '{}')\n", format_text));
        return exit_usage;
    }
    std::optional<esi::DeviceSelector> selector;
    if (!esi::cli::parse_device_option("esi-sii build", device_text, selector)) return exit_usage;
    if (const esi::Diagnostics same = esi::refuse_output_over_input(output, {input}); same.has_errors()) {
        print(stderr, esi::sii::render_diagnostics_text(same));
        return exit_usage;
    }
    const std::optional<esi::EsiDocument> document = load_document(input);
    if (!document) return exit_usage;
    const std::vector<const esi::Device*> all = esi::select_devices(*document, std::nullopt);
    const std::vector<const esi::Device*> chosen = esi::select_devices(*document, selector);
    if (all.empty()) {
        print(stderr, fmt::format("esi-sii build: {} describes no device\n", input));
        return exit_usage;
    }
    if (chosen.empty()) {
        print(stderr, fmt::format("esi-sii build: no device of {} matches --device {}; the file has:\n{}", input, device_text,
                                  device_list(all)));
        return exit_usage;
    }
    if (chosen.size() > 1) {
        print(stderr, fmt::format("esi-sii build: {} has {} devices{}; choose one with --device:\n{}", input, chosen.size(),
                                  selector ? " matching --device " + device_text : "", device_list(chosen)));
        return exit_usage;
    }
    const esi::Device& device = *chosen.front();
    const esi::sii::BuildResult result = esi::sii::build_image(*document->info_of(device), device, options, input);
    print(stderr, esi::sii::render_diagnostics_text(result.diagnostics));
    if (!result.ok()) {
        print(stderr, fmt::format("esi-sii build: no image written for {}\n", device_label(device)));
        return exit_usage;
    }
    const std::string comment = fmt::format("{}, vendor 0x{:08X}", device_label(device), result.image.header.vendor_id);
    const esi::Diagnostics written =
        esi::write_file_atomically(output, esi::sii::format_image(result.bytes, format, "sii_eeprom", comment));
    if (written.has_errors()) {
        print(stderr, esi::sii::render_diagnostics_text(written));
        return exit_usage;
    }
    return exit_ok;
}

int run_dump(const std::string& image_path, const std::string& format) {
    if (format != "text" && format != "json") {
        print(stderr, fmt::format("esi-sii dump: --format must be text or json (not '{}')\n", format));
        return exit_usage;
    }
    const esi::sii::LoadedImage loaded = esi::sii::load_image_file(image_path);
    if (!loaded.bytes) {
        print(stderr, fmt::format("esi-sii dump: {}: {}\n", image_path, loaded.error));
        return exit_usage;
    }
    const esi::sii::DecodedImage decoded = esi::sii::decode_image(*loaded.bytes);
    print(stdout, format == "json" ? esi::sii::render_dump_json(decoded, image_path) : esi::sii::render_dump_text(decoded, image_path));
    return decoded.has_errors() ? exit_findings : exit_ok;
}

int run_check(const std::string& esi_path, const std::string& image_path) {
    const esi::sii::LoadedImage loaded = esi::sii::load_image_file(image_path);
    if (!loaded.bytes) {
        print(stderr, fmt::format("esi-sii check: {}: {}\n", image_path, loaded.error));
        return exit_usage;
    }
    const std::optional<esi::EsiDocument> document = load_document(esi_path);
    if (!document) return exit_usage;
    const std::vector<const esi::Device*> all = esi::select_devices(*document, std::nullopt);
    if (all.empty()) {
        print(stderr, fmt::format("esi-sii check: {} describes no device\n", esi_path));
        return exit_usage;
    }
    const esi::sii::DecodedImage decoded = esi::sii::decode_image(*loaded.bytes);
    const esi::sii::ImageDevice match = esi::sii::find_device_for_image(*document, decoded.image.header);
    if (!match.device) {
        print(stdout, esi::sii::render_faults_text(decoded, image_path));
        print(stdout, fmt::format("{}: product code 0x{:08X} (revision 0x{:08X}) is not in {}, which has:\n{}", image_path,
                                  decoded.image.header.product_code, decoded.image.header.revision_no, esi_path, device_list(all)));
        return exit_findings;
    }
    const esi::Diagnostics mismatches = esi::sii::check_image(*match.info, *match.device, decoded, esi_path, image_path);
    print(stdout, esi::sii::render_check_text(decoded, image_path, mismatches, device_label(*match.device)));
    return decoded.has_errors() || mismatches.has_errors() ? exit_findings : exit_ok;
}

}  // namespace

namespace {

int run_tool(int argc, char** argv) {
    esi::cli::exit_with_code_two_when_out_of_memory("esi-sii");
    esi::install_leftover_cleanup();
    CLI::App app{"esi-sii: build, dump and check SII EEPROM images"};
    app.require_subcommand(1);
    esi::cli::add_version_flag(app, "esi-sii");

    std::string build_input, build_output, build_device, build_format = "bin";
    bool no_pdo = false, no_dc = false, strict_size = false;
    CLI::App* build = app.add_subcommand("build", "write the SII image of an ESI or YAML device");
    build->add_option("input", build_input, "ESI.xml or SOURCE.yaml")->required();
    build->add_option("-o,--output", build_output, "image file to write")->required();
    esi::cli::add_device_option(*build, build_device, "the device, when the file has several");
    build->add_option("--format", build_format, "image file format: bin (default), hex (Intel HEX) or c (C array)");
    build->add_flag("--no-pdo", no_pdo, "leave out the TxPDO/RxPDO categories");
    build->add_flag("--no-dc", no_dc, "leave out the DC category");
    build->add_flag("--strict-size", strict_size,
                    "refuse an image larger than Eeprom/ByteSize instead of leaving out optional content until it fits");

    std::string dump_image, dump_format = "text";
    CLI::App* dump = app.add_subcommand("dump", "decode an image (binary or Intel HEX) and report its faults");
    dump->add_option("image", dump_image, "IMAGE.bin or IMAGE.hex")->required();
    dump->add_option("--format", dump_format, "text (default) or json");

    std::string check_esi, check_image;
    CLI::App* check = app.add_subcommand("check", "compare an image with its ESI device (ETG conformance ESI tests)");
    check->add_option("esi", check_esi, "ESI.xml")->required();
    check->add_option("image", check_image, "IMAGE.bin or IMAGE.hex")->required();

    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;
    if (build->parsed()) {
        esi::sii::BuildOptions options;
        options.include_pdos = !no_pdo;
        options.include_dc = !no_dc;
        options.fit_to_eeprom = !strict_size;
        return run_build(build_input, build_output, build_device, build_format, options);
    }
    if (dump->parsed()) return run_dump(dump_image, dump_format);
    if (check->parsed()) return run_check(check_esi, check_image);
    return exit_usage;
}

}  // namespace

int main(int argc, char** argv) { return esi::cli::exit_with_stdout_checked("esi-sii", run_tool(argc, argv)); }
