// The SyncManager watchdog under SOEM 2.x: a master cycling keeps the device in OP; a master
// that stops finds the watchdog expired, the device in SAFEOP with "SyncManager watchdog"
// (0x001B) and its outputs in the safe state (with --echo the inputs show them: 0); cycling again
// and acknowledging the error brings it back to OP.

#include <gtest/gtest.h>

#include "sim_esc/soem_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

TEST(SoemWatchdog, StoppingTheCycleExpiresItAndCyclingKeepsItAlive) {
    ESI_REQUIRE_SOEM();
    // A 100 ms watchdog, a 1 ms cycle for 300 ms, then 300 ms of silence: wide margins, so a
    // loaded machine neither lets it expire while cycling nor misses the expiry.
    const auto results = run_soem_session(
        {{{(source_dir() / "samples" / "digital-io-8.yaml").string(), "--echo"},
          {"--cycles", "300", "--cycle-us", "1000", "--watchdog-ms", "100", "--stop-ms", "300", "--echo"}}});
    ASSERT_EQ(results.size(), 1u);
    ASSERT_TRUE(results[0].report) << results[0].sim_stderr << results[0].master_output;
    const auto& r = *results[0].report;
    ASSERT_EQ(r["op"], true) << results[0].master_output;
    // Cycling: the outputs arrive in time, nothing expires.
    EXPECT_EQ(r["wkc_ok"], r["cycles"]);
    EXPECT_EQ(r["echo_ok"], r["echo_checked"]);
    const auto& stopped = r["stopped"];
    EXPECT_EQ(stopped["watchdog_counter_before"], 0);
    EXPECT_EQ(stopped["al_status_before"], 0x08);
    // Silence: expired, counted once, the device in SAFEOP with the error and 0x001B.
    EXPECT_EQ(stopped["watchdog_status"].get<unsigned>() & 1, 0u);
    EXPECT_EQ(stopped["watchdog_counter"], 1);
    EXPECT_EQ(stopped["al_status"], 0x14);
    EXPECT_EQ(stopped["al_status_code"], 0x001B);
    EXPECT_EQ(stopped["inputs_zero"], true) << "the outputs were not put in their safe state";
    EXPECT_EQ(stopped["back_in_op"], true);
    EXPECT_EQ(r["slave"][0]["state"], 8);
}

}  // namespace
}  // namespace esi::test
