#pragma once
// One diagnostic as one line on stderr, the way every tool but esi-lint (which has its own
// formats) reports: `path:line:col: severity: message [rule]`.

#include <iostream>
#include <string_view>

#include "esi/diagnostic.hpp"

inline void print_diagnostic_line(const esi::Diagnostic& d, std::string_view path_when_unknown) {
    std::cerr << (d.path.empty() ? path_when_unknown : std::string_view(d.path));
    if (d.pos.known()) std::cerr << ':' << d.pos.line << ':' << d.pos.column;
    std::cerr << ": " << esi::to_string(d.severity) << ": " << d.message << " [" << d.rule << "]\n";
}
