// A modular device runs with the modules its slots hold by default (ETG.2001): their PDOs in
// the assignment objects and the process image, their objects at the slot's indices.

#include <gtest/gtest.h>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

// samples/modular-coupler.yaml: slot 1 holds EX-M-DI8 and slot 2 EX-M-DO8 by default; PDO
// increment 1 and index increment 0x10 per slot.
class ModularDevice : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.ready());
        ASSERT_TRUE(bench.master->to_preop());
    }
    Bench bench{"samples/modular-coupler.yaml"};
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
