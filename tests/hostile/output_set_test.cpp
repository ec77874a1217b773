// One run's output set (issue 16): runs into the same output directory take turns under its
// lock, a failed run removes the directories it created, and an interrupted run removes its
// temporary files, created directories and lock file.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "esi/io/atomic_write.hpp"
#include "esi/io/leftovers.hpp"
#include "hostile/hostile_support.hpp"
#include "io/leftover_registry.hpp"
#include "support/test_support.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using esi::test::run_child;

std::string gen_tool() { return esi::test::tool("esi-gen").string(); }
std::string sample_path() { return (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string(); }

// The sample with a second device: esi-gen then writes one subdirectory per device.
std::string two_device_esi() {
    const std::string sample = esi::test::sample_esi();
    const auto begin = sample.find("<Device ");
    const auto end = sample.find("</Device>") + std::string("</Device>").size();
    std::string second = sample.substr(begin, end - begin);
    second = esi::test::replace_once(second, "ProductCode=\"#x00001001\"", "ProductCode=\"#x00001002\"");
    second = esi::test::replace_once(second, ">EX-DIO-8</Type>", ">EX-DIO-8-B</Type>");
    return sample.substr(0, end) + "\n" + second + sample.substr(end);
}

pid_t spawn(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return spawned == 0 ? pid : -1;
}

TEST(OutputSet, ARunWaitsWhileTheOutputDirectoryIsLocked) {
    esi::test::TempDir dir;
    const fs::path out = dir / "out";
    fs::create_directories(out);
    // Another writer holds the lock, as a second esi-gen run (or `flock out/.esi-output.lock make`) would.
    const int held = open((out / ".esi-output.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    ASSERT_GE(held, 0);
    ASSERT_EQ(flock(held, LOCK_EX), 0);

    const pid_t gen = spawn({gen_tool(), sample_path(), "-o", out.string()});
    ASSERT_GT(gen, 0);
    int status = 0;
    // Well beyond a run's duration (about 0.1 s): the run must still be waiting.
    for (int i = 0; i < 20; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        ASSERT_EQ(waitpid(gen, &status, WNOHANG), 0) << "esi-gen wrote while another writer held the directory's lock";
    }
    EXPECT_EQ(esi::test::snapshot(out).size(), 1u) << "only the lock file, no output yet";

    // Released the way a run releases it: the file goes first, then the lock.
    unlink((out / ".esi-output.lock").c_str());
    close(held);
    ASSERT_EQ(waitpid(gen, &status, 0), gen);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const auto written = esi::test::snapshot(out);
    EXPECT_GE(written.size(), 5u);
    EXPECT_EQ(written.count(".esi-output.lock"), 0u) << "the lock file is removed after the run";
}

TEST(OutputSet, ConcurrentRunsLeaveOneRunsSet) {
    esi::test::TempDir dir;
    // Two sources that produce the same file names with different contents.
    const std::string first = esi::test::sample_esi();
    const std::string second = esi::test::replace_once(first, "Example Automation GmbH", "Other Automation GmbH");
    esi::test::write_text(dir / "a" / "example-digital-io.xml", first);
    esi::test::write_text(dir / "b" / "example-digital-io.xml", second);
    ASSERT_EQ(run_child({gen_tool(), (dir / "a" / "example-digital-io.xml").string(), "-o", (dir / "ref-a").string()}).exit_code, 0);
    ASSERT_EQ(run_child({gen_tool(), (dir / "b" / "example-digital-io.xml").string(), "-o", (dir / "ref-b").string()}).exit_code, 0);
    const auto set_a = esi::test::snapshot(dir / "ref-a");
    const auto set_b = esi::test::snapshot(dir / "ref-b");
    ASSERT_NE(set_a, set_b);
    for (int round = 0; round < 10; ++round) {
        const fs::path out = dir / ("out" + std::to_string(round));
        const pid_t a = spawn({gen_tool(), (dir / "a" / "example-digital-io.xml").string(), "-o", out.string()});
        const pid_t b = spawn({gen_tool(), (dir / "b" / "example-digital-io.xml").string(), "-o", out.string()});
        int status_a = 0, status_b = 0;
        ASSERT_EQ(waitpid(a, &status_a, 0), a);
        ASSERT_EQ(waitpid(b, &status_b, 0), b);
        EXPECT_TRUE(WIFEXITED(status_a) && WEXITSTATUS(status_a) == 0);
        EXPECT_TRUE(WIFEXITED(status_b) && WEXITSTATUS(status_b) == 0);
        const auto result = esi::test::snapshot(out);
        EXPECT_TRUE(result == set_a || result == set_b) << "round " << round << ": the files come from both runs";
    }
}

TEST(OutputSet, AFailedRunRemovesTheDirectoriesItCreated) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "two.xml", two_device_esi());
    ASSERT_EQ(run_child({gen_tool(), (dir / "two.xml").string(), "-o", (dir / "reference").string()}).exit_code, 0);
    const auto fresh = esi::test::snapshot(dir / "reference");
    std::size_t largest = 0;
    for (const auto& [name, content] : fresh) largest = std::max(largest, content.size());
    ASSERT_TRUE(fs::is_directory(dir / "reference" / "ex_dio_8_b"));

    // A full disk, as RLIMIT_FSIZE: the largest file cannot be written.
    esi::test::ChildOptions options;
    options.file_size_limit = largest - 1;
    options.ignore_sigxfsz = true;
    for (const fs::path& out : {dir / "new" / "deeper", dir / "existing"}) {
        SCOPED_TRACE(out.string());
        if (out.filename() == "existing") fs::create_directories(out);
        const auto gen = run_child({gen_tool(), (dir / "two.xml").string(), "-o", out.string()}, options);
        EXPECT_EQ(gen.exit_code, 1) << gen.err;
        EXPECT_NE(gen.err.find("[io-error]"), std::string::npos) << gen.err;
        if (out.filename() == "existing") {
            EXPECT_TRUE(fs::is_directory(out)) << "a directory the run did not create stays";
            EXPECT_TRUE(fs::is_empty(out)) << "the per-device directories and the lock file are gone";
        } else {
            EXPECT_FALSE(fs::exists(dir / "new")) << "the output directory and its parent were created by the failed run";
        }
    }
}

// The mechanism behind the tools' signal handling, in a child process.
TEST(OutputSet, AnInterruptedRunRemovesWhatItRegistered) {
    esi::test::TempDir dir;
    const fs::path file = dir / ".device.xml.tmp123";
    const fs::path created = dir / "created";
    const fs::path nested = created / "nested";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        esi::install_leftover_cleanup();
        fs::create_directories(nested);
        const esi::io_detail::LeftoverRegistration outer(created, esi::io_detail::LeftoverKind::directory);
        const esi::io_detail::LeftoverRegistration inner(nested, esi::io_detail::LeftoverKind::directory);
        esi::test::write_text(file, "complete copy");
        const esi::io_detail::LeftoverRegistration temporary(file, esi::io_detail::LeftoverKind::file);
        raise(SIGTERM);
        _exit(0);  // not reached: the signal ends the child
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "the signal still ends the process";
    EXPECT_FALSE(fs::exists(file));
    EXPECT_FALSE(fs::exists(created));
}

TEST(OutputSet, SigtermAtRandomPointsLeavesNoTemporaryOrLockFile) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "two.xml", two_device_esi());
    auto duration = std::chrono::microseconds::max();
    for (int i = 0; i < 3; ++i) {
        const auto started = std::chrono::steady_clock::now();
        ASSERT_EQ(run_child({gen_tool(), (dir / "two.xml").string(), "-o", (dir / "reference").string()}).exit_code, 0);
        duration = std::min(duration, std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - started));
    }
    const auto fresh = esi::test::snapshot(dir / "reference");
    std::mt19937 random(16);
    std::uniform_int_distribution<long> delay(0, duration.count() * 3 / 2);
    int terminated = 0;
    for (int round = 0; round < 30; ++round) {
        const fs::path out = dir / ("run" + std::to_string(round));
        const pid_t gen = spawn({gen_tool(), (dir / "two.xml").string(), "-o", out.string()});
        ASSERT_GT(gen, 0);
        std::this_thread::sleep_for(std::chrono::microseconds(delay(random)));
        kill(gen, SIGTERM);
        int status = 0;
        ASSERT_EQ(waitpid(gen, &status, 0), gen);
        if (WIFSIGNALED(status)) {
            EXPECT_EQ(WTERMSIG(status), SIGTERM);
            ++terminated;
        }
        if (!fs::exists(out)) continue;  // ended before it created anything
        for (const auto& [name, content] : esi::test::snapshot(out)) {
            EXPECT_EQ(name.find(".tmp"), std::string::npos) << "round " << round << ": temporary file " << name << " left";
            EXPECT_NE(name, ".esi-output.lock") << "round " << round;
            EXPECT_TRUE(fresh.count(name) && fresh.at(name) == content) << "round " << round << ": " << name << " is not complete";
        }
    }
    std::cout << "[          ] " << terminated << " of 30 esi-gen runs ended by SIGTERM\n";
}

}  // namespace
