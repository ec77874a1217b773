#pragma once
// One diagnostic on stderr, the way every tool but esi-lint (which has its own report formats)
// reports: `path:line:col: severity: message [rule]` and its notes (esi::format_diagnostic).

#include <cstdio>
#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"

inline void print_diagnostic(const esi::Diagnostic& d, std::string_view path_when_unknown) {
    const std::string text = esi::format_diagnostic(d, {.path_when_unknown = path_when_unknown});
    std::fwrite(text.data(), 1, text.size(), stderr);
}
