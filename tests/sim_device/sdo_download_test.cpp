// SDO downloads to the model slave: expedited, normal and segmented, complete access, and the
// abort codes of writes (ETG.1000.6 Table 41).

#include <gtest/gtest.h>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

class SdoDownload : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.ready());
        ASSERT_TRUE(bench.master->to_preop());
    }
    Bench bench{remappable};
    TestMaster& m() { return *bench.master; }
};

TEST_F(SdoDownload, ExpeditedWriteReadsBack) {
    EXPECT_EQ(m().download(0x7000, 1, le(0xBEEF, 2)), 0u);
    EXPECT_EQ(m().upload(0x7000, 1).data, le(0xBEEF, 2));
    EXPECT_EQ(m().download(0x2003, 0, {9}), 0u);
    EXPECT_EQ(m().upload(0x2003, 0).data, std::vector<std::uint8_t>{9});
}

TEST_F(SdoDownload, SegmentedWriteOfALongStringReadsBack) {
    std::vector<std::uint8_t> text(300);
    for (std::size_t i = 0; i < text.size(); ++i) text[i] = static_cast<std::uint8_t>('a' + i % 26);
    EXPECT_EQ(m().download(0x2000, 0, text), 0u);
    EXPECT_EQ(m().upload(0x2000, 0).data, text);
    // Seven bytes per segment, the initiate frame carrying none.
    std::vector<std::uint8_t> other(45, 'z');
    EXPECT_EQ(m().download_segmented(0x2000, 0, other), 0u);
    std::vector<std::uint8_t> expected = other;
    expected.resize(300, 0);  // a shorter string is padded with NUL
    EXPECT_EQ(m().upload(0x2000, 0).data, expected);
}

TEST_F(SdoDownload, SegmentedUploadCarriesTheWholeDefault) {
    const SdoResult r = m().upload(0x2000, 0);
    ASSERT_EQ(r.abort, 0u);
    ASSERT_EQ(r.data.size(), 300u);
    EXPECT_EQ(std::string(r.data.begin(), r.data.begin() + 19), "The quick brown fox");
}

TEST_F(SdoDownload, WriteOfReadOnlyIsAborted) { EXPECT_EQ(m().download(0x2002, 0, le(1, 4)), 0x06010002u); }

TEST_F(SdoDownload, ReadOfWriteOnlyIsAborted) {
    EXPECT_EQ(m().download(0x2001, 0, le(1, 4)), 0u);
    EXPECT_EQ(m().upload(0x2001, 0).abort, 0x06010001u);
}

TEST_F(SdoDownload, WrongLengthsAreAborted) {
    EXPECT_EQ(m().download(0x7000, 3, le(1, 2)), 0x06070013u);  // UDINT written with 2 bytes
    EXPECT_EQ(m().download(0x7000, 1, le(1, 4)), 0x06070012u);  // UINT written with 4 bytes
    EXPECT_EQ(m().download(0x2003, 0, le(1, 8)), 0x06070012u);  // normal transfer, too long
    EXPECT_EQ(m().download(0x2000, 0, std::vector<std::uint8_t>(301, 'x')), 0x06070012u);
}

TEST_F(SdoDownload, MissingTargetsAreAborted) {
    EXPECT_EQ(m().download(0x5FFF, 0, le(1, 2)), 0x06020000u);
    EXPECT_EQ(m().download(0x7000, 9, le(1, 2)), 0x06090011u);
}

TEST_F(SdoDownload, AbsurdAnnouncedSizeIsRefusedAtOnce) {
    // Initiate download announcing 4 GiB: refused before any segment.
    auto a = m().exchange(3, {0x00, 0x20, 0x21, 0x00, 0x20, 0x00, 0xFF, 0xFF, 0xFF, 0xFF});
    ASSERT_TRUE(a);
    EXPECT_EQ((*a)[8], 0x80);
    EXPECT_EQ((*a)[12] | ((*a)[13] << 8) | ((*a)[14] << 16) | (static_cast<std::uint32_t>((*a)[15]) << 24), 0x06070012u);
}

TEST_F(SdoDownload, SegmentWithTheWrongToggleIsAborted) {
    auto a = m().exchange(3, {0x00, 0x20, 0x21, 0x00, 0x20, 0x00, 20, 0, 0, 0});  // 20 bytes to 0x2000, none carried
    ASSERT_TRUE(a);
    ASSERT_EQ((*a)[8], 0x60);
    auto s = m().exchange(3, {0x00, 0x20, 0x10, 'a', 'b', 'c', 'd', 'e', 'f', 'g'});  // toggle 1 first
    ASSERT_TRUE(s);
    EXPECT_EQ((*s)[8], 0x80);
    EXPECT_EQ((*s)[12] | ((*s)[13] << 8) | ((*s)[14] << 16) | (static_cast<std::uint32_t>((*s)[15]) << 24), 0x05030000u);
}

TEST_F(SdoDownload, UploadSegmentWithoutATransferIsAborted) {
    auto a = m().exchange(3, {0x00, 0x20, 0x60, 0, 0, 0, 0, 0, 0, 0});
    ASSERT_TRUE(a);
    EXPECT_EQ((*a)[8], 0x80);
}

TEST_F(SdoDownload, CompleteAccessReadsTheWholeObject) {
    const SdoResult r = m().upload(0x6000, 0, true);
    ASSERT_EQ(r.abort, 0u);
    // Sub-index 0 (3) padded to 16 bits, then 0x1111, 7, 0x33333333.
    EXPECT_EQ(r.data, (std::vector<std::uint8_t>{3, 0, 0x11, 0x11, 7, 0, 0x33, 0x33, 0x33, 0x33}));
    const SdoResult from1 = m().upload(0x6000, 1, true);
    EXPECT_EQ(from1.data, (std::vector<std::uint8_t>{0x11, 0x11, 7, 0, 0x33, 0x33, 0x33, 0x33}));
}

TEST_F(SdoDownload, CompleteAccessWritesTheWholeObject) {
    EXPECT_EQ(m().download(0x7000, 1, {1, 0, 2, 0, 3, 0, 0, 0}, true), 0u);
    EXPECT_EQ(m().upload(0x7000, 1).data, le(1, 2));
    EXPECT_EQ(m().upload(0x7000, 2).data, le(2, 2));
    EXPECT_EQ(m().upload(0x7000, 3).data, le(3, 4));
    EXPECT_EQ(m().download(0x7000, 1, std::vector<std::uint8_t>(12, 0), true), 0x06070012u);
}

}  // namespace
}  // namespace esi::sim::test_bench
