#pragma once
// Helpers for the hostile-input and nothing-lost tests: run a tool as a child process with
// resource limits and measure its peak memory, build hostile inputs, snapshot a directory.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace esi::test {

struct ChildOptions {
    std::optional<std::uint64_t> file_size_limit;  // RLIMIT_FSIZE in bytes
    std::optional<std::uint64_t> address_space_limit;  // RLIMIT_AS in bytes
    bool ignore_sigxfsz = false;                    // write() then fails with EFBIG instead of a kill
    std::optional<std::chrono::microseconds> kill_after;  // SIGKILL the child after this long
    std::string stdin_data;
    std::string stdin_file;  // when set, the child's stdin is this file (e.g. /dev/zero)
};

struct ChildResult {
    int exit_code = -1;    // when the child exited
    int signal = 0;        // when a signal ended it
    std::string out;
    std::string err;
    long max_rss_kb = 0;   // peak resident set of the child (wait4 rusage)
    [[nodiscard]] bool exited() const { return signal == 0; }
};

ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options = {});

// Memory bounds are stated for the plain build; the sanitizer build's allocator and shadow
// memory need more, so bounds are scaled by this factor there.
int memory_scale();

// Whether this process can be denied reading by file permissions (false for root).
bool permissions_apply();

// Every regular file under `dir` (relative path -> content), for before/after comparisons.
std::map<std::string, std::string> snapshot(const std::filesystem::path& dir);

// The bundled sample ESI file's text.
std::string sample_esi();

// Replaces the first occurrence of `from` in `text`; the test fails when it is absent.
std::string replace_once(std::string text, const std::string& from, const std::string& to);

// A TCP listener on 127.0.0.1 that records whether anything connected (tests that prove no
// network access: a URL pointing at it must never be fetched).
class Listener {
public:
    Listener();
    ~Listener();
    Listener(const Listener&) = delete;
    Listener& operator=(const Listener&) = delete;
    [[nodiscard]] int port() const { return port_; }
    [[nodiscard]] bool anyone_connected() const;

private:
    int fd_ = -1;
    int port_ = 0;
};

// 1-based line number of the first occurrence of `needle` in `text` (0 when absent).
std::uint32_t line_of(const std::string& text, const std::string& needle);

}  // namespace esi::test
