// esi-net: master-side configuration from ESI files (docs/esi-net.md).
//   esi-net build NETWORK.yaml -o OUTDIR [--only eni,igh,lcec,map,html,ros2] [--esi PATH...] [--templates DIR...]
//   esi-net init --from-igh SLAVES.txt [--esi PATH...] -o NETWORK.yaml
//   esi-net init --from-eni network.xml --esi PATH... [--omit-unknown] -o NETWORK.yaml
//   esi-net find [--esi PATH...] [--vendor NAME] [--format text|json] [VENDOR:PRODUCT[:REVISION] | NAME]
//   esi-net check [--network NETWORK.yaml] [--esi PATH...] [--igh-slaves F] [--igh-pdos F] [--soem F] [--sii N=F] [--format text|json]
// Exit codes: 0 done; 1 the network has errors (an unknown device, a PDO selection the ESI
// forbids …) or nothing was found or written; 2 usage error or an unreadable or invalid input
// file. Nothing is written on error.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <fmt/format.h>
#include <iostream>

#include "cli_common.hpp"
#include "diagnostic_line.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/doc/process_image_page.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/io/read_file.hpp"
#include "esi/net/bus_check.hpp"
#include "esi/net/bus_dump.hpp"
#include "esi/net/eni_import.hpp"
#include "esi/net/device_search.hpp"
#include "esi/net/igh_scan.hpp"
#include "esi/net/library_index.hpp"
#include "esi/net/network.hpp"
#include "esi/net/outputs.hpp"
#include "esi/net/resolve.hpp"
#include "esi/net/ros2_config.hpp"

namespace {

namespace fs = std::filesystem;
using esi::cli::exit_findings;
using esi::cli::exit_ok;
using esi::cli::exit_usage;

void print(const esi::Diagnostics& diagnostics) {
    esi::Diagnostics sorted = diagnostics;
    sorted.sort();
    for (const auto& d : sorted) print_diagnostic(d, "esi-net");
}

esi::net::IndexOptions index_options(bool no_cache) {
    esi::net::IndexOptions options;
    if (!no_cache) options.cache_dir = esi::net::default_cache_dir();
    return options;
}

std::vector<fs::path> paths(const std::vector<std::string>& texts) { return {texts.begin(), texts.end()}; }

int run_build(const std::string& network_path, const std::string& output_dir, const std::string& only,
              const std::vector<std::string>& esi, bool no_cache, const std::vector<fs::path>& template_dirs) {
    std::string error;
    const auto kinds = only.empty() ? std::optional<std::vector<esi::net::OutputKind>>(std::vector<esi::net::OutputKind>(
                                          esi::net::all_output_kinds().begin(), esi::net::all_output_kinds().end()))
                                    : esi::net::parse_output_kinds(only, error);
    if (!kinds) {
        std::cerr << "esi-net build: --only: " << error << "\n";
        return exit_usage;
    }
    const esi::net::NetworkFileResult read = esi::net::read_network_file(network_path);
    print(read.diagnostics);
    if (!read.spec) return exit_usage;
    esi::net::BuildOptions options;
    options.extra_esi = paths(esi);
    options.index = index_options(no_cache);
    const esi::net::BuildResult built = esi::net::build_network(*read.spec, options);
    print(built.diagnostics);
    if (!built.network) {
        std::cerr << "esi-net build: " << network_path << ": nothing written\n";
        return exit_findings;
    }
    std::vector<esi::OutputFile> files = esi::net::network_outputs(*built.network, *kinds, output_dir);
    if (std::find(kinds->begin(), kinds->end(), esi::net::OutputKind::html) != kinds->end()) {
        esi::doc::ProcessImagePageOptions page_options;
        page_options.template_dirs = template_dirs;
        esi::doc::ProcessImagePage page = esi::doc::render_process_image_page(*built.network, output_dir, page_options);
        print(page.diagnostics);
        if (page.diagnostics.has_errors()) {
            std::cerr << "esi-net build: " << network_path << ": nothing written\n";
            return exit_findings;
        }
        std::move(page.files.begin(), page.files.end(), std::back_inserter(files));
    }
    if (std::find(kinds->begin(), kinds->end(), esi::net::OutputKind::ros2) != kinds->end()) {
        esi::net::Ros2Output ros2 = esi::net::ros2_outputs(*built.network, output_dir);
        // Asked for by name, a ROS 2 configuration the driver cannot take stops the run. Only
        // implied by the default set, it must not cost the user the ENI, IgH and lcec files: the
        // ros2 files are left out, and the findings say why as warnings.
        const bool asked_for = !only.empty();
        const bool left_out = ros2.diagnostics.has_errors() && !asked_for;
        if (left_out)
            for (esi::Diagnostic& d : ros2.diagnostics.items())
                if (d.severity == esi::Severity::error) d.severity = esi::Severity::warning;
        print(ros2.diagnostics);
        if (ros2.diagnostics.has_errors()) {
            std::cerr << "esi-net build: " << network_path << ": nothing written (leave ros2 out with --only)\n";
            return exit_findings;
        }
        if (left_out)
            std::cerr << "esi-net build: " << network_path << ": ros2 left out (ethercat_driver_ros2 cannot take this network; --only ros2 makes it an error)\n";
        else
            std::move(ros2.files.begin(), ros2.files.end(), std::back_inserter(files));
    }
    // One output set, as the other tools write theirs: under the directory's lock, replaced whole
    // or not at all.
    const esi::Diagnostics written = esi::write_output_set(output_dir, files);
    print(written);
    return written.has_errors() ? exit_findings : exit_ok;
}

int run_find(const std::string& query_text, const std::string& vendor, const std::string& format, const std::vector<std::string>& esi,
             bool no_cache) {
    if (format != "text" && format != "json") {
        std::cerr << "esi-net find: --format is text or json, not '" << format << "'\n";
        return exit_usage;
    }
    if (query_text.empty() && vendor.empty()) {
        std::cerr << "esi-net find: give a device (name, part of a name or VENDOR:PRODUCT[:REVISION]) and/or --vendor NAME\n";
        return exit_usage;
    }
    std::optional<esi::net::DeviceQuery> query;
    if (!query_text.empty()) {
        std::string error;
        query = esi::net::parse_find_query(query_text, error);
        if (!query) {
            std::cerr << "esi-net find: " << error << "\n";
            return exit_usage;
        }
    }
    if (esi.empty()) {
        std::cerr << "esi-net find: give the ESI library with --esi PATH\n";
        return exit_usage;
    }
    const std::optional<std::string> vendor_filter = vendor.empty() ? std::nullopt : std::optional<std::string>(vendor);
    esi::net::IndexOptions options = index_options(no_cache);
    esi::net::IndexResult indexed = esi::net::build_library_index(paths(esi), options);
    esi::net::DeviceSearch found = esi::net::search_devices(indexed.index, query, vendor_filter);
    const auto devices_of = [](const esi::net::DeviceSearch& search) {
        std::vector<const esi::net::IndexedDevice*> out;
        for (const esi::net::DeviceMatch& m : search.matches) out.push_back(m.device);
        return out;
    };
    if (indexed.stats.cached > 0 && !esi::net::index_agrees_with_files(indexed.index, devices_of(found))) {
        // What the cache said is not what the files hold: the answer comes from the files.
        options.rescan = true;
        indexed = esi::net::build_library_index(paths(esi), options);
        found = esi::net::search_devices(indexed.index, query, vendor_filter);
    }
    print(indexed.diagnostics);
    if (indexed.diagnostics.has_errors()) return exit_usage;
    print(found.diagnostics);
    esi::cli::write_stdout(format == "json" ? esi::net::device_search_json(indexed.index, found)
                                            : esi::net::device_search_text(indexed.index, found));
    return found.matches.empty() ? exit_findings : exit_ok;
}

int run_init(const std::string& scan_path, const std::string& output, const std::vector<std::string>& esi, bool no_cache) {
    std::string error;
    const std::optional<std::string> text = esi::read_file_bytes(scan_path, error);
    if (!text) {
        std::cerr << "esi-net init: " << scan_path << ": " << error << "\n";
        return exit_usage;
    }
    const esi::net::IghScan scan = esi::net::parse_igh_slaves(*text, scan_path);
    print(scan.diagnostics);
    if (scan.diagnostics.has_errors()) return exit_usage;
    std::optional<esi::net::LibraryIndex> index;
    if (!esi.empty()) {
        esi::net::IndexResult indexed = esi::net::build_library_index(paths(esi), index_options(no_cache));
        print(indexed.diagnostics);
        if (indexed.diagnostics.has_errors()) return exit_usage;
        index = std::move(indexed.index);
    }
    esi::net::InitOptions options;
    // `build` reads `esi:` relative to the network file, so that is how they are written.
    const fs::path network_dir = fs::absolute(fs::path(output)).lexically_normal().parent_path();
    for (const std::string& e : esi) {
        const fs::path absolute = fs::absolute(e).lexically_normal();
        const fs::path relative = absolute.lexically_relative(network_dir);
        options.esi.push_back((relative.empty() ? absolute : relative).generic_string());
    }
    const esi::net::InitResult init = esi::net::network_from_scan(scan, index ? &*index : nullptr, options);
    print(init.diagnostics);
    if (init.diagnostics.has_errors()) {
        std::cerr << "esi-net init: " << output << ": nothing written\n";
        return exit_findings;
    }
    const esi::Diagnostics written = esi::write_file_atomically(output, init.yaml);
    print(written);
    return written.has_errors() ? exit_findings : exit_ok;
}

int run_init_from_eni(const std::string& eni_path, const std::string& output, const std::vector<std::string>& esi, bool no_cache,
                      bool omit_unknown) {
    std::string error;
    const std::optional<std::string> text = esi::read_file_bytes(eni_path, error);
    if (!text) {
        std::cerr << "esi-net init: " << eni_path << ": " << error << "\n";
        return exit_usage;
    }
    if (esi.empty()) {
        std::cerr << "esi-net init --from-eni: give the ESI library with --esi PATH (the network says only what the ESI does not)\n";
        return exit_usage;
    }
    const esi::net::IndexResult indexed = esi::net::build_library_index(paths(esi), index_options(no_cache));
    print(indexed.diagnostics);
    if (indexed.diagnostics.has_errors()) return exit_usage;
    esi::net::EniImportOptions options;
    options.esi = esi;
    options.omit_unknown = omit_unknown;
    const esi::net::EniImport imported = esi::net::network_from_eni(*text, eni_path, indexed.index, options);
    print(imported.diagnostics);
    if (imported.yaml.empty()) {
        std::cerr << "esi-net init: " << eni_path << ": nothing written\n";
        return imported.diagnostics.has_errors() ? exit_usage : exit_findings;
    }
    const esi::Diagnostics written = esi::write_file_atomically(output, imported.yaml);
    print(written);
    return written.has_errors() ? exit_findings : exit_ok;
}

struct CheckInputs {
    std::string network, igh_slaves, igh_pdos, soem, format = "text";
    std::vector<std::string> sii;  // POSITION=FILE
};

int run_check(const CheckInputs& in, const std::vector<std::string>& esi, bool no_cache) {
    if (in.format != "text" && in.format != "json") {
        std::cerr << "esi-net check: --format is text or json\n";
        return exit_usage;
    }
    std::vector<std::vector<esi::net::BusSlave>> dumps;
    esi::Diagnostics read_problems;
    auto read = [&](const std::string& path, auto parse) -> bool {
        if (path.empty()) return true;
        std::string error;
        const std::optional<std::string> text = esi::read_file_bytes(path, error);
        if (!text) {
            std::cerr << "esi-net check: " << path << ": " << error << "\n";
            return false;
        }
        esi::net::BusDump dump = parse(*text, path);
        read_problems.append(dump.diagnostics);
        dumps.push_back(std::move(dump.slaves));
        return true;
    };
    if (!read(in.soem, esi::net::parse_soem_slaveinfo) || !read(in.igh_pdos, esi::net::parse_igh_pdos)) return exit_usage;
    // Identities first: the other dumps add SMs, FMMUs and PDOs to the slaves they name.
    if (!read(in.igh_slaves, esi::net::parse_igh_slaves_dump)) return exit_usage;
    if (!in.igh_slaves.empty()) std::rotate(dumps.begin(), dumps.end() - 1, dumps.end());
    std::vector<esi::net::SiiDump> sii;
    for (const std::string& arg : in.sii) {
        const std::size_t eq = arg.find('=');
        esi::net::SiiDump d;
        std::string error;
        try {
            if (eq == std::string::npos) throw std::invalid_argument("no '='");
            d.position = std::stoul(arg.substr(0, eq));
        } catch (const std::exception&) {
            std::cerr << "esi-net check: --sii takes POSITION=FILE (the output of `ethercat sii_read -p POSITION`), not '" << arg << "'\n";
            return exit_usage;
        }
        d.path = arg.substr(eq + 1);
        const std::optional<std::string> bytes = esi::read_file_bytes(d.path, error);
        if (!bytes) {
            std::cerr << "esi-net check: " << d.path << ": " << error << "\n";
            return exit_usage;
        }
        d.bytes.assign(bytes->begin(), bytes->end());
        sii.push_back(std::move(d));
    }
    print(read_problems);
    if (read_problems.has_errors()) return exit_usage;
    if (dumps.empty() && sii.empty()) {
        std::cerr << "esi-net check: give what the bus reports: --soem, --igh-pdos, --igh-slaves and/or --sii\n";
        return exit_usage;
    }
    std::optional<esi::net::Network> network;
    std::vector<std::string> library = esi;
    esi::net::IndexOptions index_opts = index_options(no_cache);
    if (!in.network.empty()) {
        const esi::net::NetworkFileResult spec = esi::net::read_network_file(in.network);
        print(spec.diagnostics);
        if (!spec.spec) return exit_usage;
        esi::net::BuildOptions options;
        options.extra_esi = paths(esi);
        options.index = index_opts;
        esi::net::BuildResult built = esi::net::build_network(*spec.spec, options);
        print(built.diagnostics);
        if (!built.network) return exit_findings;
        network = std::move(built.network);
        const fs::path base = fs::path(in.network).parent_path();
        for (const std::string& e : spec.spec->esi) library.push_back(fs::path(e).is_absolute() ? e : (base / e).string());
    }
    if (library.empty()) {
        std::cerr << "esi-net check: give the ESI library with --esi PATH (or a --network whose esi: names it)\n";
        return exit_usage;
    }
    const esi::net::IndexResult indexed = esi::net::build_library_index(paths(library), index_opts);
    print(indexed.diagnostics);
    if (indexed.diagnostics.has_errors()) return exit_usage;
    const esi::net::CheckResult result = esi::net::check_bus(esi::net::merge_bus_dumps(dumps), sii, network ? &*network : nullptr, indexed.index);
    if (in.format == "json") {
        esi::cli::write_stdout(esi::net::check_result_json(result));
    } else {
        std::string out;
        for (const esi::net::CheckedSlave& s : result.slaves)
            out += fmt::format("slave {} {}: {}{}\n", s.position, s.name.empty() ? "?" : s.name, s.esi.empty() ? "no ESI" : s.esi,
                               s.findings ? fmt::format(", {} finding{}", s.findings, s.findings == 1 ? "" : "s") : ", as the ESI says");
        esi::cli::write_stdout(out);
        print(result.findings);
    }
    return result.findings.has_errors() ? exit_findings : exit_ok;
}

}  // namespace

namespace {

int run_tool(int argc, char** argv) {
    CLI::App app{"esi-net: master configuration (ENI, IgH C, linuxcnc-ethercat, ROS 2, process-image map) from ESI files"};
    app.require_subcommand(1);
    esi::cli::add_version_flag(app, "esi-net");

    std::string build_network_path, build_output, build_only;
    std::vector<std::string> build_esi, find_esi, init_esi;
    bool no_cache = false;
    app.add_flag("--no-cache", no_cache, "do not read or write the ESI library index cache ($XDG_CACHE_HOME/libesi)");
    CLI::App* build = app.add_subcommand("build", "write the master configuration of a network");
    build->add_option("network", build_network_path, "NETWORK.yaml")->required();
    build->add_option("-o,--output", build_output, "output directory (created when missing)")->required();
    build->add_option("--only", build_only, "output kinds, comma-separated: eni, igh, lcec, map, html, ros2 (default: all)");
    build->add_option("--esi", build_esi, "more ESI files or folders to look in (repeatable)");
    std::vector<std::string> build_templates;
    build->add_option("--templates", build_templates, "directory searched for the html page's templates before the built-in ones (repeatable)");

    std::string scan_path, init_output;
    std::string eni_path;
    bool omit_unknown = false;
    CLI::App* init = app.add_subcommand("init", "write a NETWORK.yaml from a bus scan or an ENI");
    CLI::Option* from_igh = init->add_option("--from-igh", scan_path, "output of the IgH master's `ethercat slaves -v`");
    init->add_option("--from-eni", eni_path, "an ENI (network.xml) of TwinCAT, EC-Engineer or esi-net; needs --esi")->excludes(from_igh);
    init->add_flag("--omit-unknown", omit_unknown, "--from-eni: write slaves no ESI describes as comments");
    init->add_option("--esi", init_esi, "ESI files or folders to name the devices from (repeatable)");
    init->add_option("-o,--output", init_output, "NETWORK.yaml to write")->required();

    CheckInputs check_inputs;
    std::vector<std::string> check_esi;
    CLI::App* check = app.add_subcommand("check", "compare what a running bus reports with the ESI files and the network");
    check->add_option("--network", check_inputs.network, "NETWORK.yaml the bus should match (default: each device's ESI defaults)");
    check->add_option("--esi", check_esi, "ESI files or folders (repeatable)");
    check->add_option("--igh-slaves", check_inputs.igh_slaves, "output of IgH's `ethercat slaves -v`");
    check->add_option("--igh-pdos", check_inputs.igh_pdos, "output of IgH's `ethercat pdos`");
    check->add_option("--soem", check_inputs.soem, "output of SOEM's `slaveinfo IF -map`");
    check->add_option("--sii", check_inputs.sii, "POSITION=FILE: an SII image (`ethercat sii_read -p POSITION`), repeatable");
    check->add_option("--format", check_inputs.format, "text (default) or json");

    std::string query, find_vendor, find_format = "text";
    CLI::App* find = app.add_subcommand("find", "which ESI file describes a device");
    find->add_option("device", query, "VENDOR:PRODUCT[:REVISION], a device name or part of one (Type text or Name)");
    find->add_option("--vendor", find_vendor, "only devices of this vendor (part of its name, or its id); alone: all its devices");
    // One path per --esi: the device is optional (--vendor alone), so a greedy --esi would take it.
    find->add_option("--esi", find_esi, "an ESI file or folder to look in (repeat --esi for more)")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    find->add_option("--format", find_format, "text (default) or json");

    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;
    if (build->parsed()) {
        std::vector<fs::path> user_dirs;
        if (!esi::cli::parse_template_dirs("esi-net build", build_templates, user_dirs)) return exit_usage;
        const std::vector<fs::path> template_dirs = esi::doc::template_search_path(user_dirs, esi::cli::executable_path(argc > 0 ? argv[0] : nullptr));
        return run_build(build_network_path, build_output, build_only, build_esi, no_cache, template_dirs);
    }
    if (init->parsed()) {
        if (!eni_path.empty()) return run_init_from_eni(eni_path, init_output, init_esi, no_cache, omit_unknown);
        if (scan_path.empty()) {
            std::cerr << "esi-net init: give --from-igh SLAVES.txt or --from-eni network.xml\n";
            return exit_usage;
        }
        return run_init(scan_path, init_output, init_esi, no_cache);
    }
    if (find->parsed()) return run_find(query, find_vendor, find_format, find_esi, no_cache);
    if (check->parsed()) return run_check(check_inputs, check_esi, no_cache);
    return exit_usage;
}

}  // namespace

int main(int argc, char** argv) { return esi::cli::exit_with_stdout_checked("esi-net", run_tool(argc, argv)); }
