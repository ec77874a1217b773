// A modular device runs with the modules its slots hold by default (ETG.2001): their PDOs in
// the assignment objects and the process image, their objects at the slot's indices.

#include <gtest/gtest.h>

#include "esi/net/default_slave.hpp"
#include "sim/slotted_device.hpp"
#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

// fixtures/modular-mandatory.yaml: slot 1 holds EX-M-DI8 and slot 2 EX-M-DO8 by default (both
// mandatory, so esi-net places them); PDO increment 1 and index increment 0x10 per slot.
class ModularDevice : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.ready());
        ASSERT_TRUE(bench.master->to_preop());
    }
    Bench bench{"tests/sim_device/fixtures/modular-mandatory.yaml"};
    TestMaster& m() { return *bench.master; }
};

TEST_F(ModularDevice, AssignmentHoldsTheDefaultModulesPdos) {
    EXPECT_EQ(m().upload(0x1C12, 0).data, std::vector<std::uint8_t>{1});
    EXPECT_EQ(m().upload(0x1C12, 1).data, (std::vector<std::uint8_t>{0x01, 0x16}));
    EXPECT_EQ(m().upload(0x1C13, 0).data, std::vector<std::uint8_t>{1});
    EXPECT_EQ(m().upload(0x1C13, 1).data, (std::vector<std::uint8_t>{0x00, 0x1A}));
    // The DO8 module's first entry: 0x7010:01, one bit.
    EXPECT_EQ(m().upload(0x1601, 1).data, (std::vector<std::uint8_t>{0x01, 0x01, 0x10, 0x70}));
}

TEST_F(ModularDevice, ModuleObjectsSitAtTheSlotsIndices) {
    EXPECT_EQ(m().upload(0x6000, 0).data, std::vector<std::uint8_t>{8});   // DI8 in slot 1
    EXPECT_EQ(m().upload(0x7010, 0).data, std::vector<std::uint8_t>{8});   // DO8 in slot 2
    EXPECT_EQ(m().upload(0x7000, 0).abort, 0x06020000u);                   // no DO8 in slot 1
}

TEST_F(ModularDevice, ReachesOpWithTheModulesProcessData) {
    m().configure_process_sm(2, 1);
    m().configure_process_sm(3, 1);
    EXPECT_EQ(m().request_state(4), 4);
    EXPECT_EQ(m().request_state(8), 8);
}

}  // namespace
}  // namespace esi::sim::test_bench

namespace esi::sim::test_bench {
namespace {

// esi-sim's line hands the stack a device with its modules already in place
// (sim/slotted_device.hpp); the stack must not add them a second time.
TEST(ModularDeviceExpanded, ModulesAlreadyInPlaceAreNotAddedAgain) {
    auto sample = load_sample("tests/sim_device/fixtures/modular-mandatory.yaml");
    ASSERT_TRUE(sample);
    Diagnostics diagnostics;
    const net::DefaultSlave configured = net::configure_default_slave(*sample->info, *sample->device, diagnostics);
    const Device expanded = device_with_modules(configured.slave);
    ASSERT_GT(expanded.tx_pdos.size(), sample->device->tx_pdos.size());
    FakeEsc esc;
    auto slave = make_model_slave(*sample->info, expanded, {}, diagnostics);
    ASSERT_TRUE(slave);
    TestMaster m(esc, *slave, *sample->info, expanded);
    ASSERT_TRUE(m.to_preop());
    EXPECT_EQ(m.upload(0x1C13, 0).data, std::vector<std::uint8_t>{1});
    EXPECT_EQ(m.upload(0x1C12, 0).data, std::vector<std::uint8_t>{1});
    m.configure_process_sm(2, 1);
    m.configure_process_sm(3, 1);
    EXPECT_EQ(m.request_state(4), 4);
}

}  // namespace
}  // namespace esi::sim::test_bench

namespace esi::sim::test_bench {
namespace {

// Slots that need no module stay empty, as esi-net leaves them.
TEST(ModularDeviceOptionalSlots, NoModuleWhereNoneIsNeeded) {
    Bench b("samples/modular-coupler.yaml");
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    EXPECT_EQ(b.master->upload(0x6000, 0).abort, 0x06020000u);
    b.master->configure_process_sm(2, 0);
    b.master->configure_process_sm(3, 0);
    EXPECT_EQ(b.master->request_state(4), 4);
}

}  // namespace
}  // namespace esi::sim::test_bench
