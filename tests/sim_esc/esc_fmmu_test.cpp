// FMMUs: logical addressing, bit-granular mapping, registers as targets, LRW working counters.

#include <gtest/gtest.h>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {
namespace {

using esc::Command;

std::vector<std::uint8_t> fmmu(std::uint32_t logical, std::uint16_t length, std::uint8_t start_bit, std::uint8_t stop_bit,
                               std::uint16_t physical, std::uint8_t physical_bit, std::uint8_t type) {
    return {static_cast<std::uint8_t>(logical), static_cast<std::uint8_t>(logical >> 8),
            static_cast<std::uint8_t>(logical >> 16), static_cast<std::uint8_t>(logical >> 24),
            static_cast<std::uint8_t>(length), static_cast<std::uint8_t>(length >> 8), start_bit, stop_bit,
            static_cast<std::uint8_t>(physical), static_cast<std::uint8_t>(physical >> 8), physical_bit, type, 1, 0, 0, 0};
}

void configure(esc::Esc& a, std::uint16_t address, std::vector<std::uint8_t> data) {
    FrameBuilder f;
    f.add(Command::apwr, 0, address, std::move(data));
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    ASSERT_EQ(f.wkc(payload, 0), 1);
}

TEST(EscFmmu, LrwCountsOnePerReadAndTwoPerWritePerSlave) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05));
    for (esc::Esc* e : {&a, &b}) {
        configure(*e, ethercat::reg::fmmu0, fmmu(0x10000, 1, 0, 7, 0x1000, 0, 2));
        configure(*e, ethercat::reg::fmmu0 + 16, fmmu(0x10001, 1, 0, 7, 0x1100, 0, 1));
    }
    const std::uint8_t input = 0x5C;
    a.write(0x1100, std::span<const std::uint8_t>(&input, 1));
    FrameBuilder f;
    f.add_logical(Command::lrw, 0x10000, {0xA5, 0x00});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 6);
    EXPECT_EQ(a.peek8(0x1000), 0xA5);
    EXPECT_EQ(b.peek8(0x1000), 0xA5);
    EXPECT_EQ(f.data(payload, 0)[1], 0x00);  // b, later in the line, reads its own (zero) inputs last
}

TEST(EscFmmu, BitGranularMappingsPackSeveralSlavesIntoOneByte) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05));
    configure(a, ethercat::reg::fmmu0, fmmu(0x100, 1, 0, 1, 0x1000, 0, 2));  // logical bits 0..1
    configure(b, ethercat::reg::fmmu0, fmmu(0x100, 1, 2, 3, 0x1000, 0, 2));  // logical bits 2..3
    FrameBuilder f;
    f.add_logical(Command::lwr, 0x100, {0b1110});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 2);
    EXPECT_EQ(a.peek8(0x1000), 0b10);
    EXPECT_EQ(b.peek8(0x1000), 0b11);
}

TEST(EscFmmu, ReadsIntoTheFrameOnlyTheMappedBits) {
    esc::Esc a(eeprom_image(0x05));
    configure(a, ethercat::reg::fmmu0, fmmu(0x200, 1, 4, 5, 0x1100, 1, 1));
    const std::uint8_t input = 0b0110;
    a.write(0x1100, std::span<const std::uint8_t>(&input, 1));
    FrameBuilder f;
    f.add_logical(Command::lrd, 0x200, {0x0F});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 1);
    EXPECT_EQ(f.data(payload, 0)[0], 0x3F);  // bits 4..5 from physical bits 1..2; the rest untouched
}

TEST(EscFmmu, RegistersCanBeMappedLikeSm1Status) {
    esc::Esc a(eeprom_image(0x05));
    configure(a, ethercat::reg::sm0 + 8, {0x00, 0x11, 4, 0, 0x22, 0, 1, 0});
    configure(a, ethercat::reg::fmmu0 + 32, fmmu(0x9000000, 1, 0, 0, 0x080D, 3, 1));
    const std::uint8_t reply[4] = {1, 2, 3, 4};
    a.write(0x1100, reply);
    FrameBuilder f;
    f.add_logical(Command::lrd, 0x9000000, {0});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 1);
    EXPECT_EQ(f.data(payload, 0)[0], 1);  // mailbox-full bit 3 at logical bit 0
}

TEST(EscFmmu, UnmappedLogicalAddressesDoNotCount) {
    esc::Esc a(eeprom_image(0x05));
    configure(a, ethercat::reg::fmmu0, fmmu(0x100, 2, 0, 7, 0x1000, 0, 2));
    FrameBuilder f;
    f.add_logical(Command::lrw, 0x102, {1, 2});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 0);
}

}  // namespace
}  // namespace esi::test
