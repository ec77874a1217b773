#pragma once
// The message for a tool with subcommands (esi-sii, esi-net) run without a valid one: it names
// the word that is not a subcommand, suggests the nearest, and lists the valid ones, where
// CLI11 only says "A subcommand is required".

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace esi::cli {

// The message when `app` requires a subcommand and the command line has none of its names; nullopt
// when the command line does name one (CLI11's own message then says what else is wrong).
[[nodiscard]] std::optional<std::string> subcommand_usage(const CLI::App& app, int argc, char** argv);

}  // namespace esi::cli
