// The process-data watchdog through the whole stack, frame by frame: a master that cycles keeps a
// sample in OP; when it stops, the ESC's watchdog expires, the firmware drops to SAFEOP with AL
// status code 0x001B and puts its outputs in their safe state; acknowledged, it returns to OP.

#include <gtest/gtest.h>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/line_master.hpp"
#include "sim_esc/line_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

namespace reg = ethercat::reg;
constexpr std::uint64_t ms = 1'000'000;

TEST(LineWatchdog, StoppingTheCycleExpiresItAndCyclingKeepsItAlive) {
    SampleLine sample = sample_line("digital-io-8.yaml", true);
    ASSERT_TRUE(sample.line) << sample.error;
    LineMaster master(*sample.line);
    ASSERT_TRUE(master.scan());
    LineSlave& s = master.slaves[0];
    ASSERT_TRUE(master.setup_mailbox(s));
    ASSERT_EQ(master.request_state(s, 2).state(), 2);
    // A 100 ms watchdog (100 us ticks with the default divider), a 1 ms cycle.
    ASSERT_TRUE(master.write16(s.station, reg::watchdog_time_process_data, 1000));
    const std::uint16_t expected = master.setup_process_data();
    ASSERT_EQ(expected, 3);
    ASSERT_EQ(master.request_state(s, 4).state(), 4);
    ASSERT_EQ(master.request_state(s, 8).state(), 8);
    const std::vector<std::uint8_t> outputs(master.output_image_bytes(), 0x5A);
    for (int c = 0; c < 300; ++c) {
        const auto a = master.cycle(outputs, 1 * ms);
        ASSERT_TRUE(a);
        ASSERT_EQ(a->working_counter, expected) << "cycle " << c;
    }
    EXPECT_EQ(master.read(s.station, reg::watchdog_counter_process_data, 1), std::vector<std::uint8_t>{0});
    EXPECT_EQ(master.state_of(s).al_status, 0x08);

    // 300 ms without process data: only a status read now and then.
    master.frame_gap_ns = 100 * ms;
    for (int i = 0; i < 3; ++i) master.state_of(s);
    master.frame_gap_ns = 20'000;
    const auto status = master.read16(s.station, reg::watchdog_status_process_data);
    ASSERT_TRUE(status);
    EXPECT_EQ(*status & 1, 0) << "not expired";
    EXPECT_EQ(master.read(s.station, reg::watchdog_counter_process_data, 1), std::vector<std::uint8_t>{1}) << "counted once";
    const StateResult stopped = master.state_of(s);
    EXPECT_EQ(stopped.al_status, 0x14);
    EXPECT_EQ(stopped.al_status_code, 0x001B);
    // The outputs went to their safe state (zero); with --echo the inputs show it.
    const auto safe = master.cycle(outputs, 1 * ms);
    ASSERT_TRUE(safe);
    EXPECT_EQ(safe->data, std::vector<std::uint8_t>(master.input_image_bytes(), 0));

    // Acknowledged while cycling again, the device goes back to OP.
    EXPECT_FALSE(master.acknowledge_error(s, 4).error());
    EXPECT_EQ(master.request_state(s, 8).al_status, 0x08);
}

}  // namespace
}  // namespace esi::test
