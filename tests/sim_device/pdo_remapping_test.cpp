// PDO assignment and mapping over SDO (ETG.1000.6 5.6.7.4): written in PREOP only, sub-index 0
// to zero before the entries, the checks on the entries, and the SM lengths the device then
// demands on PREOP -> SAFEOP.

#include <gtest/gtest.h>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

class PdoRemapping : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.ready());
        ASSERT_TRUE(bench.master->to_preop());
    }
    Bench bench{remappable};
    TestMaster& m() { return *bench.master; }
};

TEST_F(PdoRemapping, DefaultMappingGivesFourBytesEachWay) {
    m().configure_process_sm(2, 4);
    m().configure_process_sm(3, 4);
    EXPECT_EQ(m().request_state(4), 4);
}

TEST_F(PdoRemapping, RemappedPdoChangesTheSmLength) {
    ASSERT_EQ(m().download(0x1A00, 0, {0}), 0u);
    ASSERT_EQ(m().download(0x1A00, 1, le(0x60000110, 4)), 0u);
    ASSERT_EQ(m().download(0x1A00, 2, le(0x60000220, 4) /* wrong size: UINT is 16 bits */), 0x06040041u);
    ASSERT_EQ(m().download(0x1A00, 2, le(0x60000320, 4)), 0u);
    ASSERT_EQ(m().download(0x1A00, 0, {2}), 0u);
    EXPECT_EQ(m().upload(0x1A00, 0).data, std::vector<std::uint8_t>{2});
    m().configure_process_sm(2, 4);
    m().configure_process_sm(3, 4);
    EXPECT_EQ(m().request_state(4), 0x12);  // PREOP with error: the inputs are 6 bytes now
    EXPECT_EQ(m().al_status_code(), 0x001E);
    m().configure_process_sm(3, 6);
    EXPECT_EQ(m().request_state(4 | 0x10), 4);
}

TEST_F(PdoRemapping, EntriesNeedSubIndexZeroAtZero) {
    EXPECT_EQ(m().download(0x1600, 1, le(0x70000110, 4)), 0x06010003u);
    EXPECT_EQ(m().download(0x1C12, 1, le(0x1600, 2)), 0x06010003u);
}

TEST_F(PdoRemapping, NotMappableEntriesAreRefused) {
    ASSERT_EQ(m().download(0x1600, 0, {0}), 0u);
    EXPECT_EQ(m().download(0x1600, 1, le(0x60000110, 4)), 0x06040041u);  // an input in an RxPDO
    EXPECT_EQ(m().download(0x1600, 1, le(0x20020020, 4)), 0x06040041u);  // not mappable at all
    EXPECT_EQ(m().download(0x1600, 1, le(0x70000110, 4)), 0u);
    EXPECT_EQ(m().download(0x1600, 0, {1}), 0u);
}

TEST_F(PdoRemapping, CountAboveTheEntriesIsRefused) {
    ASSERT_EQ(m().download(0x1600, 0, {0}), 0u);
    EXPECT_EQ(m().download(0x1600, 0, {9}), 0x06090031u);
}

TEST_F(PdoRemapping, AssignmentNamesMappingsOfItsDirection) {
    ASSERT_EQ(m().download(0x1C12, 0, {0}), 0u);
    EXPECT_EQ(m().download(0x1C12, 1, le(0x1A00, 2)), 0x06090030u);
    EXPECT_EQ(m().download(0x1C12, 1, le(0x1600, 2)), 0u);
    EXPECT_EQ(m().download(0x1C12, 0, {1}), 0u);
}

TEST_F(PdoRemapping, EmptyAssignmentMeansNoOutputs) {
    ASSERT_EQ(m().download(0x1C12, 0, {0}), 0u);
    m().configure_process_sm(2, 0);
    m().configure_process_sm(3, 4);
    EXPECT_EQ(m().request_state(4), 4);
}

TEST_F(PdoRemapping, WritesOutsidePreopAreRefusedWith0x08000022) {
    m().configure_process_sm(2, 4);
    m().configure_process_sm(3, 4);
    ASSERT_EQ(m().request_state(4), 4);
    EXPECT_EQ(m().download(0x1C12, 0, {0}), 0x08000022u);
    EXPECT_EQ(m().download(0x1600, 0, {0}), 0x08000022u);
    EXPECT_EQ(m().upload(0x1C12, 1).data, le(0x1600, 2));  // reads still work
}

TEST_F(PdoRemapping, CompleteAccessWritesTheMapping) {
    // Sub-index 0 = 3, pad, then three entries.
    std::vector<std::uint8_t> stream{3, 0};
    for (std::uint32_t e : {0x70000110u, 0x70000210u, 0x70000320u}) {
        const auto b = le(e, 4);
        stream.insert(stream.end(), b.begin(), b.end());
    }
    ASSERT_EQ(m().download(0x1600, 0, stream, true), 0u);
    EXPECT_EQ(m().upload(0x1600, 0).data, std::vector<std::uint8_t>{3});
    m().configure_process_sm(2, 8);
    m().configure_process_sm(3, 4);
    EXPECT_EQ(m().request_state(4), 4);
}

}  // namespace
}  // namespace esi::sim::test_bench
