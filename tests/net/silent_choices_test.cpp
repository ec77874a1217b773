// esi-net never chooses silently (issue 27, item 4): two modules for one slot are an error; the
// same identity in two ESI files is taken in the order `esi:` gives, with a note naming the
// file taken, and refused when the two differ in what a master configures unless the slave
// names the file (`esi_file:`).

#include <gtest/gtest.h>

#include "esi/net/network_spec.hpp"
#include "net/hostile_esi.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

esi::net::BuildResult build(const fs::path& network, const std::string& yaml) {
    esi::test::write_text(network, yaml);
    const esi::net::NetworkFileResult read = esi::net::read_network_file(network.string());
    if (!read.spec) {
        esi::net::BuildResult failed;
        failed.diagnostics = read.diagnostics;
        return failed;
    }
    return esi::net::build_network(*read.spec, esi::net::BuildOptions{});
}

bool has_rule(const esi::Diagnostics& diagnostics, const std::string& rule, esi::Severity severity) {
    for (const esi::Diagnostic& d : diagnostics)
        if (d.rule == rule && d.severity == severity) return true;
    return false;
}

TEST(SilentChoices, TwoModulesForOneSlotAreAnError) {
    esi::test::TempDir dir;
    const std::string samples = (esi::test::source_dir() / "samples").string();
    const auto built = build(dir / "n.yaml", "esi: [" + samples + "/modular-coupler.yaml]\nslaves:\n  - name: C\n    device: EX-BK-4\n"
                                             "    modules: [{ slot: 1, module: EX-M-DI8 }, { slot: 1, module: EX-M-DO8 }]\n");
    EXPECT_FALSE(built.network);
    const std::string text = esi::test::diagnostics_text(built.diagnostics);
    EXPECT_NE(text.find("n.yaml:5:"), std::string::npos) << text;
    EXPECT_TRUE(has_rule(built.diagnostics, "net-module", esi::Severity::error)) << text;
}

struct TwoLibraries {
    esi::test::TempDir dir;
    TwoLibraries(const std::string& second_bit_len) {
        esi::test::HostileDevice a;
        esi::test::HostileDevice b;
        b.rx_bit_len = second_bit_len;
        fs::create_directories(dir / "a");
        fs::create_directories(dir / "z");
        // The file sorted first by path is the one esi: names last.
        esi::test::write_text(dir / "a" / "dev.xml", b.xml());
        esi::test::write_text(dir / "z" / "dev.xml", a.xml());
    }
};

TEST(SilentChoices, TheSameIdentityTwiceFollowsTheEsiOrderAndSaysWhichWasTaken) {
    TwoLibraries lib("8");
    const auto built = build(lib.dir / "n.yaml", "esi: [z, a]\nslaves:\n  - { name: D, device: Hostile }\n");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    EXPECT_NE(built.network->slaves[0].esi_path.find("/z/"), std::string::npos) << built.network->slaves[0].esi_path;
    const std::string text = esi::test::diagnostics_text(built.diagnostics);
    EXPECT_TRUE(has_rule(built.diagnostics, "net-device-duplicate", esi::Severity::info)) << text;
    EXPECT_NE(text.find("z/dev.xml"), std::string::npos) << text;
}

TEST(SilentChoices, TheSameIdentityWithDifferentConfigurationsIsRefusedUntilPicked) {
    TwoLibraries lib("16");
    const auto refused = build(lib.dir / "n.yaml", "esi: [z, a]\nslaves:\n  - { name: D, device: Hostile }\n");
    EXPECT_FALSE(refused.network);
    const std::string text = esi::test::diagnostics_text(refused.diagnostics);
    EXPECT_TRUE(has_rule(refused.diagnostics, "net-device-duplicate", esi::Severity::error)) << text;
    EXPECT_NE(text.find("a/dev.xml"), std::string::npos) << text;
    EXPECT_NE(text.find("z/dev.xml"), std::string::npos) << text;

    const auto picked = build(lib.dir / "n.yaml", "esi: [z, a]\nslaves:\n  - { name: D, device: Hostile, esi_file: a/dev.xml }\n");
    ASSERT_TRUE(picked.network) << esi::test::diagnostics_text(picked.diagnostics);
    EXPECT_NE(picked.network->slaves[0].esi_path.find("/a/"), std::string::npos);
    EXPECT_EQ(picked.network->slaves[0].pdos.at(0).entries.at(0).bit_len, 16u);
}

}  // namespace
