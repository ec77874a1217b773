// The YAML samples (samples/*.yaml, the seed devices) through every code output: each generates,
// and what it generates compiles with the strict flags.

#include <gtest/gtest.h>

#include <algorithm>

#include "codegen_test_support.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::TempDir;
using esi::test::write_text;

std::vector<std::filesystem::path> yaml_samples() {
    std::vector<std::filesystem::path> found;
    const auto dir = esi::test::source_dir() / "samples";
    if (std::filesystem::is_directory(dir))
        for (const auto& e : std::filesystem::directory_iterator(dir))
            if (e.path().extension() == ".yaml") found.push_back(e.path());
    std::sort(found.begin(), found.end());
    return found;
}

TEST(SamplesCodegen, EveryYamlSampleGeneratesCodeThatCompiles) {
    const auto samples = yaml_samples();
    if (samples.empty()) GTEST_SKIP() << "no samples/*.yaml in this tree";
    ESI_REQUIRE_COMPILERS();
    for (const auto& sample : samples) {
        SCOPED_TRACE(sample.filename().string());
        TempDir dir;
        const auto r = tc::esi_gen(sample, dir.path(), {"--only", "cpp,c,soes,structs"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const std::string inc = "-I" + dir.path().string();
        write_text(dir / "all.cpp", "#include \"object_dictionary.hpp\"\n#include \"process_image.h\"\n#include \"slave_tables.h\"\n");
        auto c = tc::compile("c++", "c++17", {inc, (dir / "all.cpp").string()});
        EXPECT_EQ(c.exit_code, 0) << c.err;
        c = tc::compile("cc", "c99", {inc, (dir / "slave_tables.c").string()});
        EXPECT_EQ(c.exit_code, 0) << c.err;
        c = tc::compile("cc", "c99", {inc, "-I" + tc::soes_stand_in_dir().string(), (dir / "objectlist.c").string()});
        EXPECT_EQ(c.exit_code, 0) << c.err;
        c = tc::compile("cc", "c99", {"-x", "c", (dir / "process_image.h").string()});
        EXPECT_EQ(c.exit_code, 0) << c.err;
    }
}

}  // namespace
