// esi-sim's command line: usage errors, unusable sources and interfaces exit 2 with a message.

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace esi::test {
namespace {

std::string sample(const std::string& name) { return (source_dir() / "samples" / name).string(); }

TEST(EsiSimCli, AnUnknownInterfaceIsAClearErrorWithExitTwo) {
    const RunResult r = run({tool("esi-sim").string(), "--iface", "no-such-if0", sample("digital-io-8.yaml")});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("esi-sim: no-such-if0: no network interface 'no-such-if0'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("slave(s) on"), std::string::npos);
}

TEST(EsiSimCli, ASourceWithErrorsExitsTwoBeforeOpeningTheInterface) {
    TempDir dir;
    write_text(dir / "broken.yaml", "vendor: { id: 0x1 }\ndevices:\n  - type: X\n    product_code: [\n");
    const RunResult r = run({tool("esi-sim").string(), "--iface", "lo", (dir / "broken.yaml").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("broken.yaml"), std::string::npos) << r.err;
}

TEST(EsiSimCli, AFileWithSeveralDevicesNeedsDevice) {
    const std::string esi = (shared_dir() / "corpus" / "esi" / "Beckhoff__EK11xx__dls-ethercat.xml").string();
    if (!have_shared_corpus()) GTEST_SKIP() << "../shared/corpus not present";
    const RunResult r = run({tool("esi-sim").string(), "--iface", "lo", esi});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("choose one with --device PRODUCTCODE[:REVISION]"), std::string::npos) << r.err;
}

TEST(EsiSimCli, DeviceAndEepromDoNotApplyToANetworkFile) {
    const RunResult r = run({tool("esi-sim").string(), "--iface", "lo", sample("networks/line.yaml"), "--device", "0x1002"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("is a network file"), std::string::npos) << r.err;
}

TEST(EsiSimCli, AMissingEepromFileIsAnError) {
    const RunResult r =
        run({tool("esi-sim").string(), "--iface", "lo", sample("digital-io-8.yaml"), "--eeprom", "/nonexistent/e.bin"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("/nonexistent/e.bin"), std::string::npos) << r.err;
}

TEST(EsiSimCli, InterfaceIsRequired) {
    const RunResult r = run({tool("esi-sim").string(), sample("digital-io-8.yaml")});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--iface"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace esi::test
