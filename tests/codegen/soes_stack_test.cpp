// The SOES set against the real SOES stack (issue 11 §3): every sample's objectlist.c, utypes.h
// and ecat_options.h (esi-gen --only soes) compile with the SOES core under SOES's own warning
// flags, link into a host program over a simulated ESC (data/soes_host/esc_sim.c) and take the
// device to Op; and SOES's own PDO remapping runs against the STÖBER sample's tables under
// AddressSanitizer without overrunning a buffer.
//
// The stack comes from ../shared/tools/soes (the SOES core and two of its applications), or from
// the SOES checkout ESI_SOES_DIR names; without either the tests skip (docs/codegen.md, "SOES").

#include <gtest/gtest.h>

#include <cstdlib>

#include "codegen_test_support.hpp"

namespace {

namespace fs = std::filesystem;
namespace tc = esi::test::codegen;
using esi::test::run;
using esi::test::source_dir;
using esi::test::TempDir;
using esi::test::write_text;

fs::path soes_root() {
    if (const char* dir = std::getenv("ESI_SOES_DIR"); dir && *dir) return dir;
    return esi::test::shared_dir() / "tools" / "soes";
}

fs::path host_dir() { return tc::data_dir() / "soes_host"; }

#define ESI_REQUIRE_SOES()                                                                                              \
    do {                                                                                                                \
        if (!fs::exists(soes_root() / "soes" / "esc_coe.c"))                                                           \
            GTEST_SKIP() << "no SOES stack at " << soes_root()                                                         \
                         << " (../shared/tools/soes, or a SOES checkout in ESI_SOES_DIR): the generated SOES sets are " \
                            "not built against it";                                                                    \
        if (!tc::have_program("cc")) GTEST_SKIP() << "no cc on PATH";                                                   \
    } while (0)

// cc with SOES's own flags (SOES cmake/Linux.cmake: -Wall -Wextra -Wconversion
// -Wno-unused-parameter -Werror), the SOES core (soes/CMakeLists.txt), the generated set in
// `generated`, the simulated ESC and `main_file`.
esi::test::RunResult build_host_program(const fs::path& generated, const fs::path& main_file, const fs::path& exe,
                                        const std::vector<std::string>& extra_flags = {}) {
    const fs::path core = soes_root() / "soes";
    std::vector<std::string> argv{"cc", "-Wall", "-Wextra", "-Wconversion", "-Wno-unused-parameter", "-Werror", "-g"};
    argv.insert(argv.end(), extra_flags.begin(), extra_flags.end());
    for (const fs::path& dir : {generated, core, core / "include" / "sys" / "gcc", host_dir()}) argv.push_back("-I" + dir.string());
    for (const char* file : {"esc.c", "esc_coe.c", "esc_foe.c", "esc_eoe.c", "esc_eep.c", "ecat_slv.c"})
        argv.push_back((core / file).string());
    for (const fs::path& file : {generated / "objectlist.c", host_dir() / "esc_sim.c", main_file}) argv.push_back(file.string());
    argv.insert(argv.end(), {"-o", exe.string()});
    return run(argv);
}

std::vector<fs::path> yaml_samples() {
    std::vector<fs::path> found;
    for (const auto& e : fs::directory_iterator(source_dir() / "samples"))
        if (e.path().extension() == ".yaml") found.push_back(e.path());
    std::sort(found.begin(), found.end());
    return found;
}

// A device with outputs only: no TxPDO, so SOES's SM3 side has nothing mapped.
constexpr const char* outputs_only_yaml = R"(vendor: { id: 0x00000E4A, name: Example Automation GmbH }
groups:
  - type: DigitalIO
    name: { en: Digital I/O }
devices:
  - type: EX-DO-2
    name: { en: EX-DO-2 two outputs }
    product_code: 0x00001003
    revision: 0x00010000
    mailbox: { size: 128, coe: { sdo_info: true } }
    objects:
      0x7000:
        name: Digital outputs
        entries:
          1: { name: Output 1, type: BOOL, access: rw, pdo: rx, default: false }
          2: { name: Output 2, type: BOOL, access: rw, pdo: rx, default: false }
    rxpdo:
      - { index: 0x1600, name: Outputs, fixed: true, entries: ["0x7000:1", "0x7000:2"] }
)";

TEST(SoesStack, EverySampleBuildsWithTheSoesCoreAndReachesOp) {
    ESI_REQUIRE_SOES();
    TempDir work;
    std::vector<fs::path> sources = yaml_samples();
    write_text(work / "outputs-only.yaml", outputs_only_yaml);
    sources.push_back(work / "outputs-only.yaml");
    for (const fs::path& source : sources) {
        SCOPED_TRACE(source.filename().string());
        const fs::path generated = work / source.stem();
        const auto gen = tc::esi_gen(source, generated, {"--only", "soes"});
        ASSERT_EQ(gen.exit_code, 0) << gen.err;
        const fs::path exe = work / (source.stem().string() + "-host");
        const auto built = build_host_program(generated, host_dir() / "link_main.c", exe);
        ASSERT_EQ(built.exit_code, 0) << built.err;
        const auto ran = run({exe.string()});
        EXPECT_EQ(ran.exit_code, 0) << ran.out << ran.err;
        EXPECT_EQ(ran.out.rfind("state 0x08", 0), 0u) << ran.out;
    }
}

TEST(SoesStack, StoeberRemappingStaysInsideTheBuffersUnderAddressSanitizer) {
    ESI_REQUIRE_SOES();
    TempDir work;
    const fs::path generated = work / "stoeber";
    const auto gen = tc::esi_gen(source_dir() / "samples" / "inverter-stoeber-mds5000.yaml", generated, {"--only", "soes"});
    ASSERT_EQ(gen.exit_code, 0) << gen.err;
    const fs::path exe = work / "remap";
    const auto built = build_host_program(generated, host_dir() / "stoeber_remap_main.c", exe,
                                          {"-fsanitize=address", "-fno-omit-frame-pointer"});
    if (built.exit_code != 0 && built.err.find("asan") != std::string::npos)
        GTEST_SKIP() << "cc cannot link with -fsanitize=address here: " << built.err;
    ASSERT_EQ(built.exit_code, 0) << built.err;
    const auto ran = run({exe.string()});
    EXPECT_EQ(ran.err.find("AddressSanitizer"), std::string::npos) << ran.err;
    EXPECT_EQ(ran.exit_code, 0) << ran.out << ran.err;
    EXPECT_NE(ran.out.find("0 failed checks"), std::string::npos) << ran.out;
}

}  // namespace
