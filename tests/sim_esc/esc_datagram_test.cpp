// Datagram commands as a line of emulated ESCs executes them (ETG.1000.4 §5.4).

#include <gtest/gtest.h>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {
namespace {

using esc::Command;

TEST(EscDatagram, BroadcastReadCountsEverySlaveAndIncrementsThePosition) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05)), c(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::brd, 0, ethercat::reg::type, {0, 0});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b, &c}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 3);
    EXPECT_EQ(f.adp(payload, 0), 3);
    EXPECT_EQ(f.data(payload, 0)[0], 0x11);
}

TEST(EscDatagram, AutoIncrementAddressesTheSlaveThatSeesZero) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05)), c(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::apwr, static_cast<std::uint16_t>(-1), ethercat::reg::station_address, {0xEA, 0x03});  // slave 1
    f.add(Command::aprd, static_cast<std::uint16_t>(-2), ethercat::reg::station_address, {0, 0});         // slave 2
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b, &c}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 1);
    EXPECT_EQ(b.peek16(ethercat::reg::station_address), 0x03EA);
    EXPECT_EQ(a.peek16(ethercat::reg::station_address), 0);
    EXPECT_EQ(f.wkc(payload, 1), 1);
}

TEST(EscDatagram, ConfiguredAddressMatchesTheStationAddressOrTheEnabledAlias) {
    esc::Esc a(eeprom_image(0x05, 0, 0x0007)), b(eeprom_image(0x05));
    FrameBuilder setup;
    setup.add(Command::apwr, 0, ethercat::reg::station_address, {0xE9, 0x03});
    setup.add(Command::apwr, static_cast<std::uint16_t>(-1), ethercat::reg::station_address, {0xEA, 0x03});
    auto payload = setup.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);

    FrameBuilder f;
    f.add(Command::fprd, 0x03EA, ethercat::reg::station_address, {0, 0});
    f.add(Command::fprd, 0x0007, ethercat::reg::station_address, {0, 0});  // alias, not enabled
    payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 1);
    EXPECT_EQ(f.data(payload, 0), (std::vector<std::uint8_t>{0xEA, 0x03}));
    EXPECT_EQ(f.wkc(payload, 1), 0);

    FrameBuilder enable;
    enable.add(Command::fpwr, 0x03E9, ethercat::reg::dl_alias, {0x01});
    enable.add(Command::fprd, 0x0007, ethercat::reg::station_address, {0, 0});
    payload = enable.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);
    EXPECT_EQ(enable.wkc(payload, 1), 1);
    EXPECT_EQ(enable.data(payload, 1), (std::vector<std::uint8_t>{0xE9, 0x03}));
}

TEST(EscDatagram, ReadWriteCountsThreeAndReturnsTheOldValue) {
    esc::Esc a(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::aprw, 0, ethercat::reg::station_address, {0x34, 0x12});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 3);
    EXPECT_EQ(f.data(payload, 0), (std::vector<std::uint8_t>{0, 0}));
    EXPECT_EQ(a.peek16(ethercat::reg::station_address), 0x1234);
}

TEST(EscDatagram, WritesToReadOnlyRegistersAreIgnoredButCounted) {
    esc::Esc a(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::apwr, 0, ethercat::reg::type, {0xFF, 0xFF, 0xFF, 0xFF});
    f.add(Command::apwr, 0, ethercat::reg::al_status, {0x08, 0x00});
    f.add(Command::apwr, 0, ethercat::reg::pdi_control, {0x00});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 1);
    EXPECT_EQ(a.peek8(ethercat::reg::type), 0x11);
    EXPECT_EQ(a.peek8(ethercat::reg::al_status), 0x01);
    EXPECT_EQ(a.peek8(ethercat::reg::pdi_control), 0x05);
}

TEST(EscDatagram, ArmwReadsAtTheAddressedSlaveAndWritesAtTheOthers) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::armw, 0, ethercat::reg::dc_system_time, std::vector<std::uint8_t>(4, 0));
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b}, 5'000'000), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 2);
    const auto read = f.data(payload, 0);
    EXPECT_EQ(read[0] | read[1] << 8 | read[2] << 16 | read[3] << 24, 5'000'000);
}

TEST(EscDatagram, ReceiveTimesAreLatchedByAWriteTo0x0900) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::bwr, 0, ethercat::reg::dc_receive_time_port0, {0});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b}, 10'000), esc::FrameOutcome::answered);
    // Slave 0 sees the frame at t, slave 1 at t + hop; it comes back to slave 0's port 1 at t + 2 hops.
    EXPECT_EQ(a.peek32(ethercat::reg::dc_receive_time_port0), 10'000u);
    EXPECT_EQ(a.peek32(ethercat::reg::dc_receive_time_port0 + 4), 11'000u);
    EXPECT_EQ(b.peek32(ethercat::reg::dc_receive_time_port0), 10'500u);
    EXPECT_EQ(b.peek32(ethercat::reg::dc_receive_time_port0 + 4), 0u);
}

TEST(EscDatagram, DlStatusShowsALineTopology) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::aprd, 0, ethercat::reg::dl_status, {0, 0});
    f.add(Command::aprd, static_cast<std::uint16_t>(-1), ethercat::reg::dl_status, {0, 0});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);
    const auto first = f.data(payload, 0), last = f.data(payload, 1);
    const unsigned s0 = first[0] | first[1] << 8, s1 = last[0] | last[1] << 8;
    EXPECT_EQ(s0 & 0x0300, 0x0200u);  // port 0 open, communication
    EXPECT_EQ(s0 & 0x0C00, 0x0800u);  // port 1 open, communication
    EXPECT_EQ(s1 & 0x0C00, 0x0400u);  // end of the line: port 1 closed
    EXPECT_TRUE(s0 & ethercat::reg::dl_status_pdi_operational);
}

TEST(EscDatagram, AClosedPort1LoopHidesTheRestOfTheLine) {
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::bwr, 0, ethercat::reg::dl_port, {0x0C});
    f.add(Command::brd, 0, ethercat::reg::type, {0});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.wkc(payload, 0), 1);
    EXPECT_EQ(f.wkc(payload, 1), 1);
}

TEST(EscDatagram, UnknownCommandsPassUnchanged) {
    esc::Esc a(eeprom_image(0x05));
    FrameBuilder f;
    f.add(static_cast<Command>(0x55), 0, 0, {1, 2, 3});
    auto payload = f.bytes();
    const auto sent = payload;
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(payload, sent);
}

}  // namespace
}  // namespace esi::test
