#pragma once
// Helpers shared by the test folders: paths to the sources, the tools and ../shared, running a
// tool and capturing its output, and skipping when the shared corpus is absent.

#include <filesystem>
#include <string>
#include <vector>

namespace esi::test {

std::filesystem::path source_dir();  // the repository
std::filesystem::path binary_dir();  // the CMake build directory
std::filesystem::path shared_dir();  // ../shared (may not exist)
std::filesystem::path corpus_esi_dir();
bool have_shared_corpus();

// The path of a built tool, e.g. tool("esi-lint").
std::filesystem::path tool(const std::string& name);

struct RunResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

// Runs a command (argv[0] is the program) with optional stdin, in `cwd` when given.
RunResult run(const std::vector<std::string>& argv, const std::string& stdin_data = {},
              const std::filesystem::path& cwd = {});

std::string read_text(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);
// Golden files are rewritten only when ESI_UPDATE_GOLDEN is exactly "1" (not "0", not empty):
// then `text` goes to `path` and the caller skips its comparison (GTEST_SKIP), so a run that
// rewrites never passes as a check.
[[nodiscard]] bool rewrite_golden(const std::filesystem::path& path, const std::string& text);

// A fresh empty directory under the system temp dir, removed by the destructor.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

// MANIFEST.tsv of the ESI corpus: file name -> notes column.
std::vector<std::pair<std::string, std::string>> corpus_manifest();

}  // namespace esi::test

// Skips the current test with a clear message when ../shared/corpus is absent.
#define ESI_REQUIRE_CORPUS()                                                                         \
    do {                                                                                             \
        if (!::esi::test::have_shared_corpus())                                                      \
            GTEST_SKIP() << "../shared/corpus not present: corpus test skipped (it runs in CI)";      \
    } while (0)
