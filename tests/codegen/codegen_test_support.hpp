#pragma once
// Helpers of the code-generation tests: the fixtures, running esi-gen into a temporary
// directory, and compiling what it wrote with the system's C and C++ compilers.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace esi::test::codegen {

inline std::filesystem::path data_dir() { return source_dir() / "tests" / "codegen" / "data"; }
inline std::filesystem::path sample_esi() { return source_dir() / "samples" / "esi" / "example-digital-io.xml"; }
inline std::filesystem::path rich_esi() { return data_dir() / "rich-device.xml"; }
inline std::filesystem::path soes_stand_in_dir() { return data_dir() / "soes"; }

// esi-gen SOURCE -o OUT [extra...]
inline RunResult esi_gen(const std::filesystem::path& source, const std::filesystem::path& out,
                         const std::vector<std::string>& extra = {}) {
    std::vector<std::string> argv{tool("esi-gen").string(), source.string(), "-o", out.string()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return run(argv);
}

// Every regular file below `dir` (relative path -> content).
inline std::map<std::string, std::string> tree(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    if (!std::filesystem::exists(dir)) return files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[std::filesystem::relative(e.path(), dir).generic_string()] = read_text(e.path());
    return files;
}

inline bool have_program(const std::string& name) { return run({"sh", "-c", "command -v " + name}).exit_code == 0; }

// Compiles (and links when `output` is given) with the strict flags the generated code promises
// to pass. Returns the compiler's result; err holds its messages.
inline RunResult compile(const std::string& compiler, const std::string& standard, const std::vector<std::string>& args,
                         const std::filesystem::path& output = {}) {
    std::vector<std::string> argv{compiler, "-std=" + standard, "-Wall", "-Wextra", "-Werror"};
    if (output.empty()) argv.push_back("-fsyntax-only");
    argv.insert(argv.end(), args.begin(), args.end());
    if (!output.empty()) {
        argv.push_back("-o");
        argv.push_back(output.string());
    }
    return run(argv);
}

}  // namespace esi::test::codegen

#define ESI_REQUIRE_COMPILERS()                                                                          \
    do {                                                                                                 \
        if (!::esi::test::codegen::have_program("cc") || !::esi::test::codegen::have_program("c++"))     \
            GTEST_SKIP() << "no cc/c++ on PATH: the generated code cannot be compiled here";             \
    } while (0)
