// esi-sim: virtual EtherCAT slaves from the model, answering a real master on a network interface.
// Exit codes: 0 stopped by SIGINT/SIGTERM, 2 usage error, unusable input or an interface that
// cannot be opened.

#include <CLI/CLI.hpp>

#include <signal.h>

#include <atomic>
#include <iostream>

#include "cli_common.hpp"
#include "diagnostic_line.hpp"
#include "out_of_memory.hpp"
#include "esi/io/read_file.hpp"
#include "esi/sim/model_slave.hpp"
#include "esi/sim/raw_socket.hpp"
#include "esi/sim/slave_setup.hpp"

namespace {

using esi::cli::exit_ok;
using esi::cli::exit_usage;

std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void request_stop(int) { stop_requested.store(true); }

void install_stop_handlers() {
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;  // no SA_RESTART: a blocked poll() returns at once
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

esi::sim::StackFactory model_slaves(bool echo) {
    return [echo](const esi::EtherCATInfo& info, const esi::Device& device, esi::Diagnostics& diagnostics) {
        return esi::sim::make_model_slave(info, device, {.echo = echo}, diagnostics);
    };
}

}  // namespace

int main(int argc, char** argv) {
    esi::cli::exit_with_code_two_when_out_of_memory("esi-sim");
    CLI::App app{"esi-sim: virtual EtherCAT slaves built from a device source, an ESI file or an esi-net network, "
                 "answering a master on a network interface"};
    std::string interface, source, device, eeprom;
    bool echo = false;
    app.add_option("SOURCE", source, "YAML device source, ESI file, or esi-net's NETWORK.yaml (a line of slaves)")
        ->required();
    app.add_option("--iface", interface, "network interface to answer EtherCAT frames on (raw socket, EtherType 0x88A4)")
        ->required();
    esi::cli::add_device_option(app, device, "the device of SOURCE to emulate, where it describes several");
    app.add_option("--eeprom", eeprom, "EEPROM image to load instead of the one built from the model (a dump, esi-gen's eeprom.bin)");
    app.add_flag("--echo", echo, "copy each slave's outputs into its inputs where the bytes line up (a loopback for tests)");
    esi::cli::add_version_flag(app, "esi-sim");
    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;

    esi::sim::SourceOptions options;
    if (!esi::cli::parse_device_option("esi-sim", device, options.device)) return exit_usage;
    if (!eeprom.empty()) options.eeprom = eeprom;

    std::string error;
    const std::optional<std::string> bytes = esi::read_file_bytes(source, error);
    if (!bytes) {
        std::cerr << "esi-sim: " << source << ": " << error << "\n";
        return exit_usage;
    }
    const bool network = esi::sim::is_network_file(*bytes);
    if (network && (options.device || options.eeprom)) {
        std::cerr << "esi-sim: " << source << " is a network file: --device and --eeprom apply to a device source\n";
        return exit_usage;
    }
    esi::sim::LineResult built = network ? esi::sim::line_from_network(source, model_slaves(echo))
                                         : esi::sim::line_from_source(source, options, model_slaves(echo));
    for (const esi::Diagnostic& d : built.diagnostics)
        if (d.severity != esi::Severity::info) print_diagnostic(d, source);
    if (!built.line) return exit_usage;

    install_stop_handlers();
    esi::sim::Line& line = *built.line;
    const esi::Diagnostics served = esi::sim::serve_interface(line, interface, stop_requested, [&] {
        std::cerr << "esi-sim: " << line.size() << " slave(s) on " << interface << std::endl;
    });
    if (served.has_errors()) {
        for (const esi::Diagnostic& d : served) std::cerr << "esi-sim: " << interface << ": " << d.message << "\n";
        return exit_usage;
    }
    return exit_ok;
}
