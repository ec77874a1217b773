// SDO Information from the model slave: the object list (fragmented as the mailbox requires),
// object and entry descriptions, and their errors.

#include <gtest/gtest.h>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

std::vector<std::uint8_t> info_request(std::uint8_t opcode, std::vector<std::uint8_t> data) {
    std::vector<std::uint8_t> r{0x00, 0x80, opcode, 0, 0, 0};
    r.insert(r.end(), data.begin(), data.end());
    return r;
}

TEST(SdoInfo, ObjectListHoldsEveryObjectInOrder) {
    Bench b("samples/inverter-stoeber-mds5000.yaml");
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    b.master->write_request(3, info_request(0x01, {0x01, 0x00}), std::nullopt);
    std::vector<std::uint16_t> listed;
    bool first = true;
    int fragments = 0;
    for (;;) {
        b.master->poll();
        auto a = b.master->read_answer();
        ASSERT_TRUE(a);
        const std::vector<std::uint8_t>& f = *a;
        ASSERT_EQ(f[5] & 0x0F, 3);
        ASSERT_EQ(f[8] & 0x7F, 0x02);
        const std::size_t length = f[0] | (f[1] << 8);
        std::size_t at = first ? 14 : 12;
        for (; at + 1 < 6 + length; at += 2) listed.push_back(static_cast<std::uint16_t>(f[at] | (f[at + 1] << 8)));
        first = false;
        ++fragments;
        if ((f[10] | (f[11] << 8)) == 0) break;
        ASSERT_LT(fragments, 1000);
    }
    const Dictionary* d = b.sample->device->dictionary();
    ASSERT_NE(d, nullptr);
    std::vector<std::uint16_t> expected;
    for (const Object& o : d->objects) expected.push_back(static_cast<std::uint16_t>(o.index));
    EXPECT_EQ(listed, expected);
    // 116 bytes of list per 128-byte mailbox (mailbox, CoE and SDO Information headers: 12).
    EXPECT_EQ(fragments, static_cast<int>((2 + 2 * expected.size() + 115) / 116));
}

TEST(SdoInfo, ObjectDescriptionGivesCodeMaxSubIndexAndName) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    auto a = b.master->exchange(3, info_request(0x03, {0x00, 0x60}));
    ASSERT_TRUE(a);
    const std::vector<std::uint8_t>& f = *a;
    EXPECT_EQ(f[8], 0x04);
    EXPECT_EQ(f[12] | (f[13] << 8), 0x6000);
    EXPECT_EQ(f[16], 3);  // max sub-index
    EXPECT_EQ(f[17], 9);  // RECORD
    const std::size_t length = f[0] | (f[1] << 8);
    EXPECT_EQ(std::string(f.begin() + 18, f.begin() + 6 + static_cast<std::ptrdiff_t>(length)), "Inputs");
}

TEST(SdoInfo, EntryDescriptionGivesTypeSizeAccessAndName) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    auto a = b.master->exchange(3, info_request(0x05, {0x00, 0x70, 0x03, 0x07}));
    ASSERT_TRUE(a);
    const std::vector<std::uint8_t>& f = *a;
    EXPECT_EQ(f[8], 0x06);
    EXPECT_EQ(f[14], 3);                      // sub-index
    EXPECT_EQ(f[16] | (f[17] << 8), 0x0007);  // UDINT
    EXPECT_EQ(f[18] | (f[19] << 8), 32);      // bits
    EXPECT_EQ(f[20] | (f[21] << 8), 0x003F | 0x0040);  // rw in every state, RxPDO-mappable
    const std::size_t length = f[0] | (f[1] << 8);
    EXPECT_EQ(std::string(f.begin() + 22, f.begin() + 6 + static_cast<std::ptrdiff_t>(length)), "Set 3");
}

TEST(SdoInfo, MissingObjectGivesAnInfoError) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    auto a = b.master->exchange(3, info_request(0x03, {0xFF, 0x5F}));
    ASSERT_TRUE(a);
    EXPECT_EQ((*a)[8], 0x07);
    EXPECT_EQ((*a)[12] | ((*a)[13] << 8) | ((*a)[14] << 16) | (static_cast<std::uint32_t>((*a)[15]) << 24), 0x06020000u);
}

TEST(SdoInfo, NotDeclaredMeansServiceNotSupported) {
    Bench b("samples/servo-item-c-series.yaml");  // sdo_info: false
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    auto a = b.master->exchange(3, info_request(0x01, {0x01, 0x00}));
    ASSERT_TRUE(a);
    EXPECT_EQ((*a)[5] & 0x0F, 0);  // mailbox error
    EXPECT_EQ((*a)[6] | ((*a)[7] << 8), 0x0001);  // mailbox command
    EXPECT_EQ((*a)[8] | ((*a)[9] << 8), 0x0004);  // service not supported
}

}  // namespace
}  // namespace esi::sim::test_bench
