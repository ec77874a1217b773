// ESI values that esi-lint calls errors, or that do not fit an output's fields, never become a
// configuration: the device is refused with a located error (issue 27, item 2).

#include <gtest/gtest.h>

#include "esi/net/network_spec.hpp"
#include "net/hostile_esi.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::test::HostileDevice;

// Builds a one-slave network naming the device by its Type text against a library holding
// only `esi`; returns the errors' rules and puts the diagnostics in `text`.
std::vector<std::string> build_errors(const std::string& esi, std::string& text, const std::string& slave = "{ name: D, device: Hostile }") {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "lib.xml", esi);
    const esi::net::NetworkFileResult read = esi::net::read_network_text("slaves:\n  - " + slave + "\n", (dir / "n.yaml").string());
    EXPECT_TRUE(read.spec) << esi::test::diagnostics_text(read.diagnostics);
    if (!read.spec) return {"unreadable"};
    esi::net::BuildOptions options;
    options.extra_esi = {dir / "lib.xml"};
    const esi::net::BuildResult built = esi::net::build_network(*read.spec, options);
    text = esi::test::diagnostics_text(built.diagnostics);
    std::vector<std::string> rules;
    for (const esi::Diagnostic& d : built.diagnostics)
        if (d.severity == esi::Severity::error) rules.push_back(d.rule);
    EXPECT_EQ(built.network.has_value(), rules.empty()) << text;
    return rules;
}

bool has(const std::vector<std::string>& rules, const std::string& rule) { return std::find(rules.begin(), rules.end(), rule) != rules.end(); }

TEST(HostileEsiValues, TheSampleDeviceBuilds) {
    std::string text;
    EXPECT_TRUE(build_errors(HostileDevice{}.xml(), text).empty()) << text;
}

TEST(HostileEsiValues, AProductCodeThatIsNotANumberIsRefusedNotTakenAsZero) {
    HostileDevice d;
    d.product_code = "#x1002G";
    std::string text;
    const auto rules = build_errors(d.xml(), text);
    EXPECT_TRUE(has(rules, "net-esi-value")) << text;
    EXPECT_NE(text.find("xml-number-format"), std::string::npos) << text;  // esi-lint's diagnostic, as a note
    EXPECT_NE(text.find("lib.xml:"), std::string::npos) << text;           // located in the ESI
}

TEST(HostileEsiValues, ANegativeBitLenIsRefusedNotMadeAZeroBitEntry) {
    HostileDevice d;
    d.rx_bit_len = "-1";
    std::string text;
    EXPECT_TRUE(has(build_errors(d.xml(), text), "net-esi-value")) << text;
}

TEST(HostileEsiValues, ABitLenBeyondAMappingEntryIsRefusedNotWrapped) {
    HostileDevice d;
    d.rx_bit_len = "4294967295";
    std::string text;
    EXPECT_TRUE(has(build_errors(d.xml(), text), "net-esi-value")) << text;
    d.rx_bit_len = "256";  // IgH's ec_pdo_entry_info_t::bit_length is uint8_t
    EXPECT_TRUE(has(build_errors(d.xml(), text), "net-esi-value")) << text;
}

TEST(HostileEsiValues, ASyncManagerRegisterBeyond16BitsIsRefused) {
    HostileDevice d;
    d.sm_start = "#x11000";
    std::string text;
    EXPECT_TRUE(has(build_errors(d.xml(), text), "net-esi-value")) << text;
}

TEST(HostileEsiValues, AnErrorInAnotherDeviceOfTheFileDoesNotRefuseThisOne) {
    HostileDevice d;
    d.second_device_product_code = "#xZZ";
    std::string text;
    EXPECT_TRUE(build_errors(d.xml(), text).empty()) << text;
}

TEST(HostileEsiValues, APdoEntryOf256BitsInTheNetworkFileIsRefused) {
    const esi::net::NetworkFileResult r =
        esi::net::read_network_text("slaves:\n  - { device: X, pdo_entries: { 0x1600: [0:0:256] } }\n", "n.yaml");
    EXPECT_FALSE(r.spec);
    EXPECT_NE(esi::test::diagnostics_text(r.diagnostics).find("n.yaml:2:"), std::string::npos) << esi::test::diagnostics_text(r.diagnostics);
}

TEST(HostileEsiValues, TheToolExitsOneAndWritesNothing) {
    HostileDevice d;
    d.product_code = "#x1002G";
    esi::test::TempDir dir;
    esi::test::write_text(dir / "lib.xml", d.xml());
    esi::test::write_text(dir / "n.yaml", "esi: [lib.xml]\nslaves:\n  - { name: D, device: Hostile }\n");
    const auto r = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "build", (dir / "n.yaml").string(), "-o", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("net-esi-value"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "network.xml"));
}

}  // namespace
