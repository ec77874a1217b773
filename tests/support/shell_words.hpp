#pragma once
// Words for the sh scripts the simulated-bus tests write (a simulator and a master started in one
// network namespace): each quoted so that no path or argument is read as shell syntax.

#include <string>
#include <vector>

namespace esi::test {

// `s` as one sh word: inside single quotes, where only ' itself needs the '\'' dance.
inline std::string shell_quoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// The arguments as sh words, each preceded by a space (to append to a command).
inline std::string shell_arguments(const std::vector<std::string>& args) {
    std::string out;
    for (const auto& a : args) out += " " + shell_quoted(a);
    return out;
}

}  // namespace esi::test
