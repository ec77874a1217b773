#pragma once
// What every tool's front end does the same way: exit codes, parsing the command line, the
// --device selector, writing results to stdout.

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/device_selector.hpp"

namespace esi::cli {

// The exit codes of every tool: 0 all well, 1 findings (lint errors, breaking changes, faults,
// a failed generation), 2 usage errors and unusable input.
inline constexpr int exit_ok = 0;
inline constexpr int exit_findings = 1;
inline constexpr int exit_usage = 2;

// Parses the command line. nullopt: go on; otherwise the tool exits with the value (0 after
// --help or --version, exit_usage after a parse error, with CLI11's message printed).
[[nodiscard]] std::optional<int> parse_or_exit(CLI::App& app, int argc, char** argv);

// --device PRODUCTCODE[:REVISION] (decimal, #x… or 0x…).
CLI::Option* add_device_option(CLI::App& app, std::string& text, const std::string& description);
// The selector written after --device; empty text selects every device. False (after printing
// `tool: --device: why` on stderr) when the text is not a selector.
[[nodiscard]] bool parse_device_option(std::string_view tool, const std::string& text, std::optional<DeviceSelector>& out);

// --version prints "tool (libesi) VERSION".
void add_version_flag(CLI::App& app, std::string_view tool);

// --templates DIR...: the directories as paths. False (after printing `tool: --templates: DIR is
// not a directory`) when one is not a directory.
[[nodiscard]] bool parse_template_dirs(std::string_view tool, const std::vector<std::string>& given,
                                       std::vector<std::filesystem::path>& out);

// The running executable, to find <prefix>/share/libesi/templates beside an installed tool.
[[nodiscard]] std::optional<std::filesystem::path> executable_path(const char* argv0);

// Writes `text` to stdout whole and flushes.
void write_stdout(std::string_view text);

// Every tool's last step: flushes standard output (C stdio and std::cout) and checks that
// everything written reached it. When it did not (a full disk, /dev/full, a closed pipe), says
// so on stderr and gives exit_usage instead of `exit_code`, so lost output is never exit 0.
//   int main(int argc, char** argv) { return esi::cli::exit_with_stdout_checked("esi-x", run(argc, argv)); }
[[nodiscard]] int exit_with_stdout_checked(std::string_view tool, int exit_code);

}  // namespace esi::cli
