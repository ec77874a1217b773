// The firmware-build integration end to end: install libesi into a temporary prefix, configure a
// project that calls esi_generate() against it, build it, run it, and check that editing the
// device description or a template regenerates what the program reads, and that a limits profile
// (CONFIG) the device breaks stops the build.

#include <gtest/gtest.h>

#include "codegen_test_support.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::read_text;
using esi::test::run;
using esi::test::RunResult;
using esi::test::TempDir;
using esi::test::write_text;

void replace_all(std::string& text, const std::string& from, const std::string& to) {
    for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
}

TEST(Consumer, InstalledPackageGeneratesTablesThatAProgramReadsAtRunTime) {
    ESI_REQUIRE_COMPILERS();
    if (!tc::have_program("cmake")) GTEST_SKIP() << "no cmake on PATH";
    TempDir dir;
    const auto prefix = dir.path() / "prefix";
    const RunResult installed = run({"cmake", "--install", esi::test::binary_dir().string(), "--prefix", prefix.string()});
    ASSERT_EQ(installed.exit_code, 0) << installed.out << installed.err;
    ASSERT_TRUE(
        std::filesystem::exists(prefix / "share" / "libesi" / "templates" / "object_dictionary.hpp.mustache"));

    // The project's own copy of the description, and one template of its own.
    std::string device = read_text(tc::sample_esi());
    write_text(dir / "device.xml", device);
    const auto templates = dir.path() / "templates";
    const std::string image_template = read_text(prefix / "share" / "libesi" / "templates" / "process_image.h.mustache");
    write_text(templates / "process_image.h.mustache", image_template + "#define CONSUMER_TEMPLATE_MARK 1\n");

    const auto build = dir.path() / "build";
    // A limits profile the device meets (esi_generate CONFIG, esi-gen --config).
    const std::string allowing = "limits: { max_pdos: 4, bitlen: [1, 8, 16, 32] }\n";
    write_text(dir / "profile.yaml", allowing);
    std::vector<std::string> configure{"cmake", "-S", (esi::test::source_dir() / "tests" / "consumer").string(), "-B", build.string(),
                                       "-DCMAKE_PREFIX_PATH=" + prefix.string(), "-DESI_CONSUMER_SOURCE=" + (dir / "device.xml").string(),
                                       "-DESI_CONSUMER_TEMPLATES=" + templates.string(),
                                       "-DESI_CONSUMER_CONFIG=" + (dir / "profile.yaml").string()};
    if (tc::have_program("ninja")) configure.insert(configure.end(), {"-G", "Ninja"});
    const RunResult configured = run(configure);
    ASSERT_EQ(configured.exit_code, 0) << configured.out << configured.err;

    auto build_and_run = [&]() -> std::string {
        const RunResult built = run({"cmake", "--build", build.string()});
        EXPECT_EQ(built.exit_code, 0) << built.out << built.err;
        const RunResult ran = run({(build / "consumer").string()});
        EXPECT_EQ(ran.exit_code, 0) << ran.out << ran.err;
        return ran.out;
    };

    std::string out = build_and_run();
    EXPECT_NE(out.find("device type 0x00001389\n"), std::string::npos) << out;
    EXPECT_NE(out.find("objects 9\n"), std::string::npos) << out;
    EXPECT_NE(out.find("rx image 1 bytes\n"), std::string::npos) << out;
    EXPECT_NE(out.find("template mark 1\n"), std::string::npos) << out;

    // Editing the description regenerates the tables.
    replace_all(device, "<DefaultValue>#x00001389</DefaultValue>", "<DefaultValue>#x00001388</DefaultValue>");
    write_text(dir / "device.xml", device);
    out = build_and_run();
    EXPECT_NE(out.find("device type 0x00001388\n"), std::string::npos) << out;

    // Editing a template regenerates too.
    write_text(templates / "process_image.h.mustache", image_template + "#define CONSUMER_TEMPLATE_MARK 2\n");
    out = build_and_run();
    EXPECT_NE(out.find("template mark 2\n"), std::string::npos) << out;

    // A profile the device breaks stops the build with esi-gen's located error, and the tables
    // stay as they were; meeting it again builds.
    write_text(dir / "profile.yaml", "limits: { bitlen: [16, 32] }\n");
    const RunResult refused = run({"cmake", "--build", build.string()});
    EXPECT_NE(refused.exit_code, 0);
    EXPECT_NE((refused.out + refused.err).find("device.xml:"), std::string::npos) << refused.out << refused.err;
    EXPECT_NE((refused.out + refused.err).find("[profile-bitlen]"), std::string::npos) << refused.out << refused.err;
    EXPECT_NE(read_text(build / "generated" / "process_image.h").find("CONSUMER_TEMPLATE_MARK 2"), std::string::npos);
    write_text(dir / "profile.yaml", allowing);
    out = build_and_run();
    EXPECT_NE(out.find("template mark 2\n"), std::string::npos) << out;
}

}  // namespace
