// A hostile master never crashes, hangs or grows the model slave: mailbox garbage, lengths
// past the buffer, repeated counters, unknown protocols and services.

#include <gtest/gtest.h>

#include <random>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

TEST(HostileMaster, UnknownProtocolGetsAMailboxError) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    for (std::uint8_t type : {1, 2, 4, 5, 15}) {
        auto a = b.master->exchange(type, {1, 2, 3, 4});
        ASSERT_TRUE(a);
        EXPECT_EQ((*a)[5] & 0x0F, 0);
        EXPECT_EQ((*a)[6] | ((*a)[7] << 8), 0x0001);  // mailbox command
        EXPECT_EQ((*a)[8] | ((*a)[9] << 8), 0x0002);  // unsupported protocol
    }
}

TEST(HostileMaster, LengthPastTheMailboxGetsInvalidSize) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    std::vector<std::uint8_t> buffer(b.master->mailbox_out_size(), 0);
    buffer[0] = 0xFF;
    buffer[1] = 0xFF;
    buffer[5] = 0x13;
    b.esc.master_write(b.master->sii_sms()->items[0].start_address, buffer);
    b.master->poll();
    auto a = b.master->read_answer();
    ASSERT_TRUE(a);
    EXPECT_EQ((*a)[5] & 0x0F, 0);
    EXPECT_EQ((*a)[8] | ((*a)[9] << 8), 0x0008);
}

TEST(HostileMaster, RepeatedCounterIsNotExecutedTwice) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    const std::vector<std::uint8_t> write{0x00, 0x20, 0x2F, 0x03, 0x20, 0x00, 0x07, 0, 0, 0};  // 0x2003 = 7
    ASSERT_TRUE(b.master->exchange(3, write, 5));
    // The same counter again: not executed, not answered.
    const std::vector<std::uint8_t> other{0x00, 0x20, 0x2F, 0x03, 0x20, 0x00, 0x09, 0, 0, 0};
    EXPECT_FALSE(b.master->exchange(3, other, 5));
    EXPECT_EQ(b.master->upload(0x2003, 0).data, std::vector<std::uint8_t>{7});
}

TEST(HostileMaster, RepeatRequestWritesTheLastAnswerAgain) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    auto first = b.master->exchange(3, {0x00, 0x20, 0x40, 0x02, 0x20, 0x00, 0, 0, 0, 0});
    ASSERT_TRUE(first);
    // Toggle the repeat request bit of SM1's activate register.
    const std::uint16_t activate = 0x0800 + 8 + 6;
    std::vector<std::uint8_t> now = b.esc.master_read(activate, 1);
    b.esc.master_write(activate, std::vector<std::uint8_t>{static_cast<std::uint8_t>(now[0] ^ 0x02)});
    b.master->poll();
    auto again = b.master->read_answer();
    ASSERT_TRUE(again);
    EXPECT_EQ(*again, *first);
    EXPECT_EQ(b.esc.master_read(0x0800 + 8 + 7, 1)[0] & 0x02, (now[0] ^ 0x02) & 0x02);  // acknowledged
}

TEST(HostileMaster, RandomMailboxesNeverBreakTheServer) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    std::mt19937 random(20);
    const std::size_t size = b.master->mailbox_out_size();
    for (int i = 0; i < 3000; ++i) {
        std::vector<std::uint8_t> buffer(size);
        for (auto& byte : buffer) byte = static_cast<std::uint8_t>(random());
        // Mostly CoE frames with plausible lengths, so the SDO server sees the garbage.
        if (i % 4 != 0) {
            buffer[0] = static_cast<std::uint8_t>(random() % (size - 6));
            buffer[1] = 0;
            buffer[5] = static_cast<std::uint8_t>((buffer[5] & 0xF0) | 3);
            buffer[7] = static_cast<std::uint8_t>((random() % 2 ? 0x20 : 0x80) | (buffer[7] & 0x0F));
        }
        b.esc.master_write(b.master->sii_sms()->items[0].start_address, buffer);
        b.master->poll(2);
        (void)b.master->read_answer();
    }
    // Still serving (counter 0 first: the garbage may have used the counter the next request gets).
    (void)b.master->exchange(3, {0x00, 0x20, 0x40, 0x02, 0x20, 0x00, 0, 0, 0, 0}, 0);
    EXPECT_EQ(b.master->upload(0x2002, 0).data, (std::vector<std::uint8_t>{42, 0, 0, 0}));
}

TEST(HostileMaster, GarbageAlControlNeverLeavesAnUnknownState) {
    Bench b(remappable);
    ASSERT_TRUE(b.ready());
    b.master->configure_mailbox();
    std::mt19937 random(7);
    for (int i = 0; i < 2000; ++i) {
        const std::uint16_t status = b.master->request_state(static_cast<std::uint16_t>(random()));
        const std::uint16_t state = status & 0x0F;
        EXPECT_TRUE(state == 1 || state == 2 || state == 3 || state == 4 || state == 8) << status;
    }
}

}  // namespace
}  // namespace esi::sim::test_bench
