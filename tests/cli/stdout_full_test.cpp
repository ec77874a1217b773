// Every tool checks that standard output was written and flushed: output sent to a full
// device (/dev/full) is an error with a message and exit code 2, never a silent exit 0
// (issue 27, item 6).

#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

esi::test::RunResult run_to_dev_full(const std::vector<std::string>& argv) {
    std::string command;
    for (const std::string& a : argv) command += "'" + a + "' ";
    return esi::test::run({"sh", "-c", command + "> /dev/full"});
}

void expect_lost_output_reported(const std::vector<std::string>& argv) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "/dev/full is not available";
    const esi::test::RunResult r = run_to_dev_full(argv);
    EXPECT_EQ(r.exit_code, 2) << argv[0] << " " << argv[1] << "\n" << r.err;
    EXPECT_NE(r.err.find("standard output"), std::string::npos) << r.err;
}

TEST(StdoutFull, EveryToolReportsItsLostVersionText) {
    for (const char* tool : {"esi-lint", "esi-gen", "esi-diff", "esi-sii", "esi-net", "esi-doc"})
        expect_lost_output_reported({esi::test::tool(tool).string(), "--version"});
}

TEST(StdoutFull, ReportsAreNotLost) {
    const std::string sample = (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string();
    expect_lost_output_reported({esi::test::tool("esi-diff").string(), "--format", "json", sample, sample});
    expect_lost_output_reported({esi::test::tool("esi-diff").string(), "--format", "html", sample, sample});
    expect_lost_output_reported({esi::test::tool("esi-lint").string(), "--format", "json", sample});
    expect_lost_output_reported({esi::test::tool("esi-lint").string(), "--list-rules"});
    expect_lost_output_reported({esi::test::tool("esi-net").string(), "--no-cache", "find", "--esi", sample, "EX-DIO-8"});
}

}  // namespace
