// Process data of the model slave: inputs from the mapped objects' values, outputs into the
// mapped objects in OP, and the echo loopback.

#include <gtest/gtest.h>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

TEST(ProcessData, InputsHoldTheMappedDefaults) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    to_op(*b.master);
    EXPECT_EQ(b.esc.master_read(sm_start(*b.master, 3), 4), (std::vector<std::uint8_t>{0x11, 0x11, 7, 0}));
}

TEST(ProcessData, OutputsReachTheMappedObjects) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    to_op(*b.master);
    const std::vector<std::uint8_t> out{0x34, 0x12, 0x78, 0x56};
    b.esc.master_write(sm_start(*b.master, 2), out);
    b.master->poll();
    EXPECT_EQ(b.master->upload(0x7000, 1).data, (std::vector<std::uint8_t>{0x34, 0x12}));
    EXPECT_EQ(b.master->upload(0x7000, 2).data, (std::vector<std::uint8_t>{0x78, 0x56}));
}

TEST(ProcessData, OutputsAreNotTakenInSafeop) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_NO_FATAL_FAILURE(to_safeop(*b.master));
    b.esc.master_write(sm_start(*b.master, 2), std::vector<std::uint8_t>{1, 2, 3, 4});
    b.master->poll();
    EXPECT_EQ(b.master->upload(0x7000, 1).data, (std::vector<std::uint8_t>{0, 0}));
}

TEST(ProcessData, EchoCopiesOutputsIntoInputs) {
    Bench b(remappable, ModelSlaveOptions{.echo = true});
    ASSERT_TRUE(b.ready());
    to_op(*b.master);
    const std::vector<std::uint8_t> out{0xA1, 0xB2, 0xC3, 0xD4};
    b.esc.master_write(sm_start(*b.master, 2), out);
    b.master->poll();
    EXPECT_EQ(b.esc.master_read(sm_start(*b.master, 3), 4), out);
}

TEST(ProcessData, SampleWithBitsEchoes) {
    Bench b("samples/digital-io-8.yaml", ModelSlaveOptions{.echo = true});
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    b.master->configure_process_sm(2, 1);
    b.master->configure_process_sm(3, 1);
    ASSERT_EQ(b.master->request_state(4), 4);
    ASSERT_EQ(b.master->request_state(8), 8);
    b.esc.master_write(sm_start(*b.master, 2), std::vector<std::uint8_t>{0x5A});
    b.master->poll();
    EXPECT_EQ(b.esc.master_read(sm_start(*b.master, 3), 1), std::vector<std::uint8_t>{0x5A});
    EXPECT_EQ(b.master->upload(0x7000, 2).data, std::vector<std::uint8_t>{1});  // bit 1 of 0x5A
    EXPECT_EQ(b.master->upload(0x7000, 1).data, std::vector<std::uint8_t>{0});
}

}  // namespace
}  // namespace esi::sim::test_bench
