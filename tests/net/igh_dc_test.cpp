// The DC calls of igh_config.c, run: the generated files are compiled against the declarations
// of IgH's documented interface (data/igh_api/ecrt.h, written for the tests) and linked with a recording stand-in for the master
// library, and a program makes the calls an application makes — <network>_configure once,
// <network>_dc_sync every cycle — so the test sees which ecrt calls reach the master, in what
// order and with which values:
//  - configure selects the ENI's reference clock (not IgH's default, the first DC-capable
//    slave: here the EK1100 coupler) and sets each DC slave's SYNC0 with ecrt_slave_config_dc;
//  - dc_sync gives the application time, sets the reference clock to it and then the slave
//    clocks, in that order, every cycle;
//  - a network without DC has no dc_sync and selects no reference clock.

#include <gtest/gtest.h>

#include <cstdio>

#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

bool have(const std::string& tool) { return esi::test::run({"/bin/sh", "-c", "command -v " + tool}).exit_code == 0; }

// Stand-ins for the master library: each call is printed, one line per call.
constexpr const char* recording_master = R"(#include <stdio.h>
#include "ecrt.h"
struct ec_master { int unused; };
static struct ec_master the_master;
ec_master_t *test_master(void) { return &the_master; }
struct ec_slave_config { unsigned position; };
static struct ec_slave_config configs[64];
ec_slave_config_t *ecrt_master_slave_config(ec_master_t *m, uint16_t alias, uint16_t position, uint32_t vendor, uint32_t product) {
    (void)m; (void)alias; configs[position].position = position;
    printf("slave_config %u 0x%08x 0x%08x\n", position, vendor, product); return &configs[position]; }
int ecrt_slave_config_pdos(ec_slave_config_t *sc, unsigned int n, const ec_sync_info_t s[]) { (void)sc; (void)n; (void)s; return 0; }
int ecrt_slave_config_sdo8(ec_slave_config_t *sc, uint16_t i, uint8_t s, uint8_t v) { (void)sc; (void)i; (void)s; (void)v; return 0; }
int ecrt_slave_config_sdo16(ec_slave_config_t *sc, uint16_t i, uint8_t s, uint16_t v) { (void)sc; (void)i; (void)s; (void)v; return 0; }
int ecrt_slave_config_sdo32(ec_slave_config_t *sc, uint16_t i, uint8_t s, uint32_t v) { (void)sc; (void)i; (void)s; (void)v; return 0; }
int ecrt_slave_config_sdo(ec_slave_config_t *sc, uint16_t i, uint8_t s, const uint8_t *d, size_t n) { (void)sc; (void)i; (void)s; (void)d; (void)n; return 0; }
int ecrt_slave_config_complete_sdo(ec_slave_config_t *sc, uint16_t i, const uint8_t *d, size_t n) { (void)sc; (void)i; (void)d; (void)n; return 0; }
int ecrt_slave_config_watchdog(ec_slave_config_t *sc, uint16_t d, uint16_t i) { (void)sc; (void)d; (void)i; return 0; }
int ecrt_slave_config_dc(ec_slave_config_t *sc, uint16_t aa, uint32_t c0, int32_t s0, uint32_t c1, int32_t s1) {
    printf("config_dc %u 0x%04x %u %d %u %d\n", sc->position, aa, c0, s0, c1, s1); return 0; }
int ecrt_master_select_reference_clock(ec_master_t *m, ec_slave_config_t *sc) { (void)m; printf("select_reference_clock %u\n", sc->position); return 0; }
int ecrt_master_application_time(ec_master_t *m, uint64_t t) { (void)m; printf("application_time %llu\n", (unsigned long long)t); return 0; }
int ecrt_master_sync_reference_clock_to(ec_master_t *m, uint64_t t) { (void)m; printf("sync_reference_clock_to %llu\n", (unsigned long long)t); return 0; }
int ecrt_master_sync_reference_clock(ec_master_t *m) { (void)m; printf("sync_reference_clock\n"); return 0; }
int ecrt_master_sync_slave_clocks(ec_master_t *m) { (void)m; printf("sync_slave_clocks\n"); return 0; }
)";

// What the application does: configure, then two cycles of 1 ms.
std::string application(const std::string& network, bool dc) {
    std::string c = "#include <stdio.h>\n#include \"igh_config.h\"\nec_master_t *test_master(void);\nint main(void) {\n"
                    "    ec_master_t *m = test_master();\n"
                    "    if (" + network + "_configure(m, NULL)) return 1;\n    printf(\"-- activate\\n\");\n";
    if (dc)
        c += "    for (uint64_t t = 1000000; t <= 2000000; t += 1000000) if (" + network + "_dc_sync(m, t)) return 2;\n";
    return c + "    return 0;\n}\n";
}

std::string run_application(const esi::net::Network& network, const std::string& name, bool dc) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "igh_config.h", esi::net::write_igh_header(network));
    esi::test::write_text(dir / "igh_config.c", esi::net::write_igh_source(network));
    esi::test::write_text(dir / "master.c", recording_master);
    esi::test::write_text(dir / "main.c", application(name, dc));
    const auto built = esi::test::run({"gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-I" + esi::test::igh_api_dir().string(), "-I" + dir.path().string(),
                                       (dir / "igh_config.c").string(), (dir / "master.c").string(), (dir / "main.c").string(), "-o",
                                       (dir / "app").string()});
    EXPECT_EQ(built.exit_code, 0) << built.err;
    if (built.exit_code != 0) return "";
    const auto ran = esi::test::run({(dir / "app").string()});
    EXPECT_EQ(ran.exit_code, 0) << ran.out << ran.err;
    return ran.out;
}

// The line the recording master prints for the axis's ecrt_slave_config_dc.
std::string fmt_dc(const esi::net::DcSetup& d) {
    char line[128];
    std::snprintf(line, sizeof line, "config_dc 1 0x%04x %u %d %u 0\n", d.assign_activate, d.cycle_time0, d.shift_time0, d.cycle_time1);
    return line;
}

TEST(IghDc, ConfigureSelectsTheEnisReferenceClockAndDcSyncRunsTheCycleCalls) {
    ESI_REQUIRE_CORPUS();
    if (!have("gcc")) GTEST_SKIP() << "no gcc: the DC calls are not run";
    // The EK1100 supports DC but runs without it; the Elmo drive runs in its DC op mode, so the
    // ENI makes the drive (position 1) the reference clock.
    const esi::net::BuildResult built = esi::test::build_corpus_network(R"(master: { cycle_time_us: 1000 }
slaves:
  - { name: coupler, device: EK1100 }
  - { name: axis, product_code: 0x00030924, revision: 0x00010420, pdos: [0x1601, 0x1A03] }
)");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    ASSERT_EQ(built.network->reference_clock, std::optional<std::size_t>(1));
    ASSERT_TRUE(built.network->slaves[1].dc);
    const std::string header = esi::net::write_igh_header(*built.network);
    EXPECT_NE(header.find("int network_dc_sync(ec_master_t *master, uint64_t app_time_ns);"), std::string::npos) << header;
    const std::string log = run_application(*built.network, "network", true);
    const std::string dc = fmt_dc(*built.network->slaves[1].dc);
    EXPECT_EQ(log, "slave_config 0 0x00000002 0x044c2c52\n"
                   "slave_config 1 0x0000009a 0x00030924\n"
                   "select_reference_clock 1\n" +
                       dc +
                       "-- activate\n"
                       "application_time 1000000\nsync_reference_clock_to 1000000\nsync_slave_clocks\n"
                       "application_time 2000000\nsync_reference_clock_to 2000000\nsync_slave_clocks\n");
}

TEST(IghDc, ANetworkWithoutDcHasNoDcCalls) {
    ESI_REQUIRE_CORPUS();
    if (!have("gcc")) GTEST_SKIP() << "no gcc: the DC calls are not run";
    const esi::net::BuildResult built = esi::test::build_corpus_network(R"(master: { dc: false }
slaves:
  - { name: coupler, device: EK1100 }
  - { name: axis, product_code: 0x00030924, revision: 0x00010420, pdos: [0x1601, 0x1A03] }
)");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    ASSERT_FALSE(built.network->reference_clock);
    EXPECT_EQ(esi::net::write_igh_header(*built.network).find("dc_sync"), std::string::npos);
    EXPECT_EQ(run_application(*built.network, "network", false),
              "slave_config 0 0x00000002 0x044c2c52\nslave_config 1 0x0000009a 0x00030924\n-- activate\n");
}

}  // namespace
