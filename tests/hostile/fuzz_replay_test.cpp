// The fuzz targets' own code, run in the normal test suite (and so under the sanitizer build)
// over their committed seeds and every saved reproducer (fuzz/regressions/<target>/): a crash
// the fuzzer once found stays fixed even where clang and libFuzzer are not available.
//
// Each fuzz/*_fuzzer.cpp defines LLVMFuzzerTestOneInput; it is renamed per target here so that
// all of them link into one test executable.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_support.hpp"

#define ESI_FUZZ_REFERENCE_ESI ESI_SOURCE_DIR "/samples/esi/example-digital-io.xml"

#define LLVMFuzzerTestOneInput xml_lint_fuzz_one
#include "../../fuzz/xml_lint_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput sii_decode_fuzz_one
#include "../../fuzz/sii_decode_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput writer_roundtrip_fuzz_one
#include "../../fuzz/writer_roundtrip_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput diff_fuzz_one
#include "../../fuzz/diff_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput codegen_fuzz_one
#include "../../fuzz/codegen_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput yaml_source_fuzz_one
#include "../../fuzz/yaml_source_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput coe_mailbox_fuzz_one
#include "../../fuzz/coe_mailbox_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput

namespace {

using FuzzOne = int (*)(const std::uint8_t*, std::size_t);

// Regular files under each directory (missing directories are skipped), sorted.
std::vector<std::filesystem::path> inputs_in(const std::vector<std::filesystem::path>& dirs) {
    std::vector<std::filesystem::path> out;
    for (const auto& dir : dirs) {
        std::error_code ec;
        if (!std::filesystem::is_directory(dir, ec)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
            if (entry.is_regular_file()) out.push_back(entry.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::size_t replay(FuzzOne fuzz_one, const std::string& target, std::vector<std::filesystem::path> seed_dirs) {
    seed_dirs.push_back(esi::test::source_dir() / "fuzz" / "regressions" / target);
    const auto files = inputs_in(seed_dirs);
    for (const auto& file : files) {
        SCOPED_TRACE(file.string());
        const std::string bytes = esi::test::read_text(file);
        EXPECT_EQ(fuzz_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
    }
    // An empty input and a single byte: the degenerate cases every target must take.
    EXPECT_EQ(fuzz_one(reinterpret_cast<const std::uint8_t*>(""), 0), 0);
    EXPECT_EQ(fuzz_one(reinterpret_cast<const std::uint8_t*>("<"), 1), 0);
    return files.size();
}

std::filesystem::path source(const std::string& relative) { return esi::test::source_dir() / relative; }

}  // namespace

TEST(FuzzReplay, XmlLint) { EXPECT_GT(replay(xml_lint_fuzz_one, "xml_lint_fuzzer", {source("samples/esi"), source("tests/rules/fixtures")}), 0u); }

TEST(FuzzReplay, SiiDecode) { EXPECT_GT(replay(sii_decode_fuzz_one, "sii_decode_fuzzer", {source("fuzz/seeds/sii")}), 0u); }

TEST(FuzzReplay, WriterRoundTrip) {
    EXPECT_GT(replay(writer_roundtrip_fuzz_one, "writer_roundtrip_fuzzer", {source("samples/esi"), source("tests/rules/fixtures")}), 0u);
}

TEST(FuzzReplay, Diff) { EXPECT_GT(replay(diff_fuzz_one, "diff_fuzzer", {source("fuzz/seeds/diff")}), 0u); }

TEST(FuzzReplay, Codegen) { EXPECT_GT(replay(codegen_fuzz_one, "codegen_fuzzer", {source("samples/esi")}), 0u); }

TEST(FuzzReplay, YamlSource) {
    EXPECT_GT(replay(yaml_source_fuzz_one, "yaml_source_fuzzer", {source("samples"), source("fuzz/seeds/yaml")}), 0u);
}

TEST(FuzzReplay, CoeMailbox) { EXPECT_GT(replay(coe_mailbox_fuzz_one, "coe_mailbox_fuzzer", {source("fuzz/seeds/coe")}), 0u); }
