// The model slave's reaction to the ESC's process-data watchdog: in OP an expiry puts the outputs
// in their safe state and the device in SAFEOP with 0x001B; OP again only once outputs arrive.

#include <gtest/gtest.h>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

TEST(SmWatchdog, ExpiryInOpGivesSafeOutputsAndSafeopWith0x001B) {
    Bench b(remappable, ModelSlaveOptions{.echo = true});
    ASSERT_TRUE(b.ready());
    to_op(*b.master);
    b.esc.rewind_watchdog();
    const std::vector<std::uint8_t> out{0x34, 0x12, 0x78, 0x56};
    b.esc.master_write(sm_start(*b.master, 2), out);
    b.master->poll();
    ASSERT_EQ(b.master->upload(0x7000, 1).data, (std::vector<std::uint8_t>{0x34, 0x12}));

    b.esc.expire_watchdog();
    b.master->poll(2);
    EXPECT_EQ(b.master->al_status(), 0x14);
    EXPECT_EQ(b.esc.u16(0x0134), 0x001B);
    EXPECT_EQ(b.master->upload(0x7000, 1).data, (std::vector<std::uint8_t>{0, 0}));
    EXPECT_EQ(b.master->upload(0x7000, 2).data, (std::vector<std::uint8_t>{0, 0}));
    EXPECT_EQ(b.esc.master_read(sm_start(*b.master, 3), 4), (std::vector<std::uint8_t>{0, 0, 0, 0}))
        << "the echo shows outputs in their safe state";

    // Acknowledged but no outputs yet: OP is refused with the same code.
    EXPECT_EQ(b.master->request_state(0x18), 0x14);
    EXPECT_EQ(b.esc.u16(0x0134), 0x001B);
    // The master writes outputs again (the ESC's watchdog is rewound): OP.
    b.esc.master_write(sm_start(*b.master, 2), out);
    b.esc.rewind_watchdog();
    EXPECT_EQ(b.master->request_state(0x18), 0x08);
}

TEST(SmWatchdog, ExpiryOutsideOpChangesNoState) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_NO_FATAL_FAILURE(to_safeop(*b.master));
    b.esc.expire_watchdog();
    b.master->poll(2);
    EXPECT_EQ(b.master->al_status(), 0x04);
    b.esc.rewind_watchdog();
    EXPECT_EQ(b.master->request_state(8), 0x08);
}

}  // namespace
}  // namespace esi::sim::test_bench
