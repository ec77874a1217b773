// esi-lsp: the Language Server Protocol server for ESI files and YAML device sources, over
// standard input and output. An editor starts it; it lints what the editor holds as esi-lint
// would and offers esi-lint's fixes.
// Exit codes: 0 after the client's shutdown and exit, 1 when the client exits or goes away
// without shutdown (the protocol's rule), 2 usage error.

#include <CLI/CLI.hpp>

#include <csignal>
#include <unistd.h>

#include "cli_common.hpp"
#include "esi/lsp/server.hpp"
#include "out_of_memory.hpp"

namespace {

int run_tool(int argc, char** argv) {
    esi::cli::exit_with_code_two_when_out_of_memory("esi-lsp");
    CLI::App app{"esi-lsp: language server for EtherCAT ESI files and YAML device sources (LSP over standard input and output)"};
    bool stdio = false;
    unsigned debounce_ms = 100;
    app.add_flag("--stdio", stdio, "talk LSP over standard input and output (the default and only transport; editors pass it)");
    app.add_option("--debounce", debounce_ms, "milliseconds a document must be unchanged before it is linted (default 100)")
        ->check(CLI::Range(0u, 10000u));
    esi::cli::add_version_flag(app, "esi-lsp");
    if (const std::optional<int> exit_code = esi::cli::parse_or_exit(app, argc, argv)) return *exit_code;

    // A client that goes away must not kill the server in the middle of a write: the write fails
    // and the server ends at the end of its input.
    std::signal(SIGPIPE, SIG_IGN);
    esi::lsp::MessageWriter out(esi::lsp::write_fd(STDOUT_FILENO));
    esi::lsp::ServerOptions options;
    options.debounce = std::chrono::milliseconds(debounce_ms);
    return esi::lsp::run_server(esi::lsp::read_fd(STDIN_FILENO), out, options);
}

}  // namespace

int main(int argc, char** argv) { return run_tool(argc, argv); }
