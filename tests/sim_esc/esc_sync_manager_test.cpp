// SyncManagers in mailbox and 3-buffer mode, from the ECAT and the PDI side.

#include <gtest/gtest.h>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {
namespace {

using esc::Command;

std::vector<std::uint8_t> sm_config(std::uint16_t start, std::uint16_t length, std::uint8_t control, std::uint8_t activate = 1) {
    return {static_cast<std::uint8_t>(start), static_cast<std::uint8_t>(start >> 8), static_cast<std::uint8_t>(length),
            static_cast<std::uint8_t>(length >> 8), control, 0, activate, 0};
}

std::uint16_t wkc_of(esc::Esc& a, Command command, std::uint16_t address, std::vector<std::uint8_t> data,
                     std::vector<std::uint8_t>* read = nullptr) {
    FrameBuilder f;
    f.add(command, 0, address, std::move(data));
    auto payload = f.bytes();
    EXPECT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    if (read) *read = f.data(payload, 0);
    return f.wkc(payload, 0);
}

TEST(EscSyncManager, MailboxOutIsRefusedWhileFullAndEmptiedByThePdi) {
    esc::Esc a(eeprom_image(0x05));
    ASSERT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0, sm_config(0x1000, 4, 0x26)), 1);
    EXPECT_EQ(wkc_of(a, Command::apwr, 0x1000, {1, 2, 3, 4}), 1);
    EXPECT_TRUE(a.peek8(0x0805) & ethercat::reg::sm_status_mailbox_full);
    EXPECT_TRUE(a.al_event() & ethercat::reg::al_event_sm(0));
    EXPECT_EQ(wkc_of(a, Command::apwr, 0x1000, {9, 9, 9, 9}), 0);  // full: refused
    EXPECT_EQ(wkc_of(a, Command::aprd, 0x1000, {0, 0, 0, 0}), 0);  // the master cannot read its own mailbox
    std::uint8_t got[4]{};
    a.read(0x1000, got);
    EXPECT_EQ(got[0], 1);
    EXPECT_EQ(got[3], 4);
    EXPECT_FALSE(a.peek8(0x0805) & ethercat::reg::sm_status_mailbox_full);
    EXPECT_FALSE(a.al_event() & ethercat::reg::al_event_sm(0));
    EXPECT_EQ(wkc_of(a, Command::apwr, 0x1000, {5, 6, 7, 8}), 1);
}

TEST(EscSyncManager, MailboxInIsReadableOnlyWhenFull) {
    esc::Esc a(eeprom_image(0x05));
    ASSERT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0 + 8, sm_config(0x1100, 4, 0x22)), 1);
    EXPECT_EQ(wkc_of(a, Command::aprd, 0x1100, {0, 0, 0, 0}), 0);
    const std::uint8_t reply[4] = {0xA, 0xB, 0xC, 0xD};
    a.write(0x1100, reply);
    EXPECT_TRUE(a.peek8(0x080D) & ethercat::reg::sm_status_mailbox_full);
    std::vector<std::uint8_t> read;
    EXPECT_EQ(wkc_of(a, Command::aprd, 0x1100, {0, 0, 0, 0}, &read), 1);
    EXPECT_EQ(read, (std::vector<std::uint8_t>{0xA, 0xB, 0xC, 0xD}));
    EXPECT_FALSE(a.peek8(0x080D) & ethercat::reg::sm_status_mailbox_full);
    EXPECT_EQ(wkc_of(a, Command::aprd, 0x1100, {0, 0, 0, 0}), 0);
}

TEST(EscSyncManager, SmConfigurationIsWriteProtectedWhileEnabled) {
    esc::Esc a(eeprom_image(0x05));
    ASSERT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0, sm_config(0x1000, 4, 0x26)), 1);
    EXPECT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0, {0x00, 0x12}), 1);
    EXPECT_EQ(a.peek16(ethercat::reg::sm0), 0x1000);
    EXPECT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0, sm_config(0x1200, 4, 0x26, 0)), 1);  // disables first? no: bytes in order
    EXPECT_EQ(a.peek16(ethercat::reg::sm0), 0x1000);
    EXPECT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0, sm_config(0x1200, 4, 0x26)), 1);     // now disabled: accepted
    EXPECT_EQ(a.peek16(ethercat::reg::sm0), 0x1200);
}

TEST(EscSyncManager, ThreeBufferOutputsGiveThePdiTheNewestCompleteImage) {
    esc::Esc a(eeprom_image(0x05));
    ASSERT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0 + 16, sm_config(0x1000, 2, 0x64)), 1);
    EXPECT_EQ(wkc_of(a, Command::apwr, 0x1000, {1, 1}), 1);
    EXPECT_EQ(wkc_of(a, Command::apwr, 0x1000, {2, 2}), 1);
    std::uint8_t got[2]{};
    a.read(0x1000, got);
    EXPECT_EQ(got[0], 2);
    // A write that stops before the last byte does not replace the newest buffer.
    EXPECT_EQ(wkc_of(a, Command::apwr, 0x1000, {3}), 1);
    a.read(0x1000, got);
    EXPECT_EQ(got[0], 2);
    EXPECT_EQ(wkc_of(a, Command::apwr, 0x1001, {3}), 1);
    a.read(0x1000, got);
    EXPECT_EQ(got[0], 3);
    EXPECT_EQ(got[1], 3);
    // The buffers live behind the first one: the previous image is still in the second.
    EXPECT_EQ(a.peek8(0x1002), 2);
}

TEST(EscSyncManager, ThreeBufferInputsKeepAReadConsistentWhileThePdiWrites) {
    esc::Esc a(eeprom_image(0x05));
    ASSERT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0 + 24, sm_config(0x1100, 2, 0x20)), 1);
    const std::uint8_t first[2] = {7, 7}, second[2] = {8, 8};
    a.write(0x1100, first);
    FrameBuilder f;
    f.add(Command::aprd, 0, 0x1100, {0});  // opens the newest buffer
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    a.write(0x1100, second);
    std::vector<std::uint8_t> rest;
    EXPECT_EQ(wkc_of(a, Command::aprd, 0x1101, {0}, &rest), 1);
    EXPECT_EQ(rest[0], 7);  // still the buffer that was open
    std::vector<std::uint8_t> next;
    EXPECT_EQ(wkc_of(a, Command::aprd, 0x1100, {0, 0}, &next), 1);
    EXPECT_EQ(next, (std::vector<std::uint8_t>{8, 8}));
}

TEST(EscSyncManager, ActivationChangesAreAnAlEventUntilThePdiReadsThem) {
    esc::Esc a(eeprom_image(0x05));
    ASSERT_EQ(wkc_of(a, Command::apwr, ethercat::reg::sm0, sm_config(0x1000, 4, 0x26)), 1);
    EXPECT_TRUE(a.al_event() & ethercat::reg::al_event_sm_activation);
    std::uint8_t act = 0;
    a.read(ethercat::reg::sm0 + ethercat::reg::sm_activate, std::span<std::uint8_t>(&act, 1));
    EXPECT_EQ(act, 1);
    EXPECT_FALSE(a.al_event() & ethercat::reg::al_event_sm_activation);
}

TEST(EscSyncManager, AlControlIsAnAlEventAndDeviceEmulationFollowsIt) {
    esc::Esc plain(eeprom_image(0x05)), emulating(eeprom_image(0x05, ethercat::reg::esc_configuration_device_emulation));
    for (esc::Esc* e : {&plain, &emulating}) EXPECT_EQ(wkc_of(*e, Command::apwr, ethercat::reg::al_control, {0x02, 0x00}), 1);
    EXPECT_TRUE(plain.al_event() & ethercat::reg::al_event_al_control);
    EXPECT_EQ(plain.peek8(ethercat::reg::al_status), 0x01);
    EXPECT_EQ(emulating.peek8(ethercat::reg::al_status), 0x02);
    std::uint8_t control[2]{};
    plain.read(ethercat::reg::al_control, control);
    EXPECT_FALSE(plain.al_event() & ethercat::reg::al_event_al_control);
    const std::uint8_t status[2] = {0x02, 0x00};
    plain.write(ethercat::reg::al_status, status);
    EXPECT_EQ(plain.peek8(ethercat::reg::al_status), 0x02);
    // Under device emulation the PDI cannot override the state the ESC shows.
    const std::uint8_t refused[2] = {0x12, 0x00};
    emulating.write(ethercat::reg::al_status, refused);
    EXPECT_EQ(emulating.peek8(ethercat::reg::al_status), 0x02);
}

}  // namespace
}  // namespace esi::test
