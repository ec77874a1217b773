#pragma once
// --color[=WHEN] for the tools that colour text output, with the NO_COLOR convention
// (https://no-color.org): colour by default only on a terminal and only when NO_COLOR is unset
// or empty; an explicit --color=always wins over NO_COLOR, so CI logs can be coloured on purpose.

#include <CLI/CLI.hpp>

#include <string>

namespace esi::cli {

// Adds --color[=auto|always|never] writing into `when` (default "auto"; --color alone is "always").
CLI::Option* add_color_option(CLI::App& app, std::string& when, const std::string& what);

// Whether to colour output written to `fd` under `when` (auto, always or never).
[[nodiscard]] bool color_enabled(const std::string& when, int fd);

}  // namespace esi::cli
