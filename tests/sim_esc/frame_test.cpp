// Malformed frames are dropped whole before any slave sees them.

#include <gtest/gtest.h>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {
namespace {

using esc::Command;

std::vector<std::uint8_t> station_write() {
    FrameBuilder f;
    f.add(Command::apwr, 0, ethercat::reg::station_address, {0x01, 0x10});
    return f.bytes();
}

TEST(EscFrame, ShortFramesAreDropped) {
    esc::Esc a(eeprom_image(0x05));
    for (std::size_t n = 0; n < 14; ++n) {
        auto payload = station_write();
        payload.resize(n);
        EXPECT_EQ(run(payload, {&a}), esc::FrameOutcome::malformed) << n;
    }
    EXPECT_EQ(a.peek16(ethercat::reg::station_address), 0);
}

TEST(EscFrame, ADatagramLengthPastTheFrameIsDropped) {
    esc::Esc a(eeprom_image(0x05));
    auto payload = station_write();
    payload[2 + 6] = 0xFF;  // data length 0x7FF
    payload[2 + 7] = 0x07;
    EXPECT_EQ(run(payload, {&a}), esc::FrameOutcome::malformed);
    EXPECT_EQ(a.peek16(ethercat::reg::station_address), 0);
}

TEST(EscFrame, AHeaderLengthPastThePayloadIsDropped) {
    esc::Esc a(eeprom_image(0x05));
    auto payload = station_write();
    payload[0] = 0xFF;
    EXPECT_EQ(run(payload, {&a}), esc::FrameOutcome::malformed);
}

TEST(EscFrame, AMoreBitWithoutAFollowingDatagramIsDropped) {
    esc::Esc a(eeprom_image(0x05));
    auto payload = station_write();
    payload[2 + 7] |= 0x80;
    EXPECT_EQ(run(payload, {&a}), esc::FrameOutcome::malformed);
    EXPECT_EQ(a.peek16(ethercat::reg::station_address), 0);
}

TEST(EscFrame, OnlyTypeOneFramesAreProcessed) {
    esc::Esc a(eeprom_image(0x05));
    auto payload = station_write();
    payload[1] = static_cast<std::uint8_t>((payload[1] & 0x0F) | 0x40);
    EXPECT_EQ(run(payload, {&a}), esc::FrameOutcome::malformed);
}

TEST(EscFrame, EthernetPaddingAfterTheDatagramsIsAccepted) {
    esc::Esc a(eeprom_image(0x05));
    auto payload = station_write();
    payload.resize(46, 0);
    EXPECT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(a.peek16(ethercat::reg::station_address), 0x1001);
}

TEST(EscFrame, ACirculatingFrameIsDestroyedAtAClosedPort0) {
    esc::Esc a(eeprom_image(0x05));
    FrameBuilder close;
    close.add(Command::bwr, 0, ethercat::reg::dl_port, {0x03});
    auto payload = close.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    auto again = station_write();
    ASSERT_EQ(run(again, {&a}), esc::FrameOutcome::answered);
    EXPECT_TRUE(again[2 + 7] & 0x40);  // marked circulating
    EXPECT_EQ(run(again, {&a}), esc::FrameOutcome::lost);
}

}  // namespace
}  // namespace esi::test
