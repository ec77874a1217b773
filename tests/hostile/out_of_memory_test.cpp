// An input too large for the memory at hand (issue 16's mutation campaign: 240 MB of deeply
// nested elements under a 2 GB address-space limit aborted esi-lint and esi-sii build with
// std::bad_alloc) is an unreadable input: a message and exit code 2, never an abort.

#include <gtest/gtest.h>

#include <string>

#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::run_child;
using esi::test::tool;

// 20 MB of nesting, which takes some 150 MB to read, against a 96 MB address space. No
// sanitizer build: its shadow memory needs terabytes of address space.
TEST(OutOfMemory, ATooLargeInputIsExitCodeTwoNotAnAbort) {
    if (esi::test::memory_scale() > 1) GTEST_SKIP() << "address-space limits do not apply under the sanitizers";
    esi::test::TempDir dir;
    std::string nested;
    for (int i = 0; i < 100'000; ++i) nested += "<SubItem><Info>";
    for (int i = 0; i < 100'000; ++i) nested += "</Info></SubItem>";
    std::string copies;
    for (int i = 0; i < 6; ++i) copies += nested;
    const std::string text = esi::test::replace_once(esi::test::sample_esi(), "<Device Physics=\"YY\">", "<Device Physics=\"YY\">" + copies);
    esi::test::write_text(dir / "large.xml", text);
    const std::string large = (dir / "large.xml").string();

    esi::test::ChildOptions options;
    options.address_space_limit = 96u << 20;
    const std::vector<std::vector<std::string>> runs = {
        {tool("esi-lint").string(), "-j", "1", large},
        {tool("esi-diff").string(), large, large},
        {tool("esi-gen").string(), large, "-o", (dir / "out").string()},
        {tool("esi-gen").string(), "--import", large, "-o", (dir / "large.yaml").string()},
        {tool("esi-sii").string(), "build", large, "-o", (dir / "large.bin").string()},
    };
    for (const auto& argv : runs) {
        SCOPED_TRACE(argv[0] + " " + argv[1]);
        const auto r = run_child(argv, options);
        ASSERT_TRUE(r.exited()) << "ended by signal " << r.signal << ": " << r.err;
        EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
        const std::string said = r.out + r.err;
        EXPECT_TRUE(said.find("not enough memory to read this file") != std::string::npos ||
                    said.find("out of memory") != std::string::npos)
            << said;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    EXPECT_FALSE(std::filesystem::exists(dir / "large.yaml"));
    EXPECT_FALSE(std::filesystem::exists(dir / "large.bin"));
}

}  // namespace
