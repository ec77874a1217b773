#pragma once
// The command-line reference rendered from a tool's CLI11 definition: the generated part of its
// man page and the option table its shell completions read. Both come from the same App object
// as --help, so neither can list an option --help lacks or miss one it has.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace esi::cli {

// NAME, SYNOPSIS (before the line `.\" esi-man-split`) and OPTIONS, COMMANDS (after it) as
// man(7) roff; cmake/EsiManPage.cmake puts them around docs/man/TOOL.1.in.
[[nodiscard]] std::string render_man_sections(const CLI::App& app, const std::string& tool);

// One line per command, positional and option, fields separated by tabs (never empty: "." is
// the tool itself, "-" no choices):
//   command    SUBCOMMAND  description
//   positional SUBCOMMAND  name
//   option     SUBCOMMAND  names (space-separated)  takes-a-value (0/1)  choices (space-separated)
// Read by completions/esi.bash, _esi (zsh) and esi.fish.
[[nodiscard]] std::string render_completion_table(const CLI::App& app);

// The hidden reference flags, given as the only argument: --help-man and --help-completion print
// the above. The exit code after printing one; nullopt when neither is asked for.
[[nodiscard]] std::optional<int> print_reference_if_asked(const CLI::App& app, int argc, char** argv);

}  // namespace esi::cli
