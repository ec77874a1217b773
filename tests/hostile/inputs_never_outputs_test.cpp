// Inputs are never outputs (issue 16): every tool that writes refuses an -o that is one of its
// inputs, however it is spelled or linked, with a located message and exit code 2, and leaves
// the input byte for byte as it was.

#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "esi/io/same_file.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::test::run;
using esi::test::tool;

TEST(InputsNeverOutputs, SameFileSeesThroughSpellingAndLinks) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "a.xml", "a");
    esi::test::write_text(dir / "copy.xml", "a");
    ASSERT_EQ(link((dir / "a.xml").c_str(), (dir / "hard.xml").c_str()), 0);
    ASSERT_EQ(symlink((dir / "a.xml").c_str(), (dir / "soft.xml").c_str()), 0);
    fs::create_directories(dir / "sub");
    ASSERT_EQ(symlink(dir.path().c_str(), (dir / "sub" / "up").c_str()), 0);

    EXPECT_TRUE(esi::same_file(dir / "a.xml", dir / "a.xml"));
    EXPECT_TRUE(esi::same_file(dir / "a.xml", dir / "sub" / ".." / "a.xml"));
    EXPECT_TRUE(esi::same_file(dir / "a.xml", dir / "hard.xml"));
    EXPECT_TRUE(esi::same_file(dir / "a.xml", dir / "soft.xml"));
    EXPECT_TRUE(esi::same_file(dir / "a.xml", dir / "sub" / "up" / "a.xml"));
    EXPECT_FALSE(esi::same_file(dir / "a.xml", dir / "copy.xml")) << "equal content is not the same file";
    EXPECT_FALSE(esi::same_file(dir / "a.xml", dir / "new.xml"));
    EXPECT_FALSE(esi::same_file(dir / "missing.xml", dir / "new.xml"));

    const esi::Diagnostics refused = esi::refuse_output_over_input(dir / "hard.xml", {dir / "copy.xml", dir / "a.xml"});
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_EQ(refused.items()[0].rule, "output-is-input");
    EXPECT_EQ(refused.items()[0].path, (dir / "hard.xml").string());
    EXPECT_NE(refused.items()[0].message.find("the same file through a link"), std::string::npos);
    EXPECT_TRUE(esi::refuse_output_over_input(dir / "new.xml", {dir / "a.xml"}).empty());
}

TEST(InputsNeverOutputs, EveryWritingToolRefusesItsInputAsOutput) {
    esi::test::TempDir dir;
    const std::string sample = esi::test::sample_esi();
    const auto input = dir / "device.xml";
    esi::test::write_text(input, sample);
    ASSERT_EQ(link(input.c_str(), (dir / "hard.xml").c_str()), 0);
    ASSERT_EQ(symlink(input.c_str(), (dir / "soft.xml").c_str()), 0);
    const std::vector<std::string> spellings = {input.string(), (dir / "." / "device.xml").string(), (dir / "hard.xml").string(),
                                                (dir / "soft.xml").string()};
    for (const auto& output : spellings) {
        SCOPED_TRACE(output);
        const std::vector<std::vector<std::string>> runs = {
            {tool("esi-gen").string(), "--import", input.string(), "-o", output},
            {tool("esi-sii").string(), "build", input.string(), "-o", output},
            {tool("esi-gen").string(), input.string(), "-o", output},
        };
        for (const auto& argv : runs) {
            SCOPED_TRACE(argv[1]);
            const auto before = esi::test::snapshot(dir.path());
            const auto r = run(argv);
            EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
            const std::string said = r.out + r.err;
            EXPECT_TRUE(said.find("[output-is-input]") != std::string::npos || said.find("[codegen-overwrites-source]") != std::string::npos)
                << said;
            EXPECT_NE(said.find("choose another output"), std::string::npos) << said;
            EXPECT_EQ(esi::test::read_text(input), sample) << "the input was replaced";
            EXPECT_EQ(esi::test::snapshot(dir.path()), before) << "something was written";
        }
    }
}

// The generated ESI file of a source in the output directory would be the source itself.
TEST(InputsNeverOutputs, EsiGenRefusesToGenerateOverItsSource) {
    esi::test::TempDir dir;
    const std::string sample = esi::test::sample_esi();
    const auto listed = run({tool("esi-gen").string(), (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string(),
                             "-o", dir.path().string(), "--list-outputs"});
    ASSERT_EQ(listed.exit_code, 0) << listed.err;
    std::string esi_output;
    for (std::size_t at = 0, end; at < listed.out.size(); at = end + 1) {
        end = listed.out.find('\n', at);
        const std::string line = listed.out.substr(at, end - at);
        if (line.size() > 4 && line.substr(line.size() - 4) == ".xml") esi_output = line;
    }
    ASSERT_FALSE(esi_output.empty()) << listed.out;
    esi::test::write_text(esi_output, sample);
    const auto before = esi::test::snapshot(dir.path());
    const auto r = run({tool("esi-gen").string(), esi_output, "-o", dir.path().string()});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("is the source file itself"), std::string::npos) << r.err;
    EXPECT_EQ(esi::test::snapshot(dir.path()), before);
}

}  // namespace
