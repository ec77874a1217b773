// The SII EEPROM as the ESC loads and serves it (ESC datasheet 0x0500..0x050F, ETG.2010).

#include <gtest/gtest.h>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {
namespace {

using esc::Command;

TEST(EscEeprom, PowerOnLoadsTheConfigurationArea) {
    esc::Esc a(eeprom_image(0x80, 0x00, 0x1234));
    EXPECT_TRUE(a.eeprom_loaded());
    EXPECT_TRUE(a.pdi_active());
    EXPECT_EQ(a.peek8(ethercat::reg::pdi_control), 0x80);
    EXPECT_EQ(a.peek16(ethercat::reg::station_alias), 0x1234);
    EXPECT_EQ(a.peek16(ethercat::reg::eeprom_control) & 0x1800, 0);
}

TEST(EscEeprom, PdiControlZeroMeansNoPdi) {
    esc::Esc a(eeprom_image(0x00));
    EXPECT_TRUE(a.eeprom_loaded());
    EXPECT_FALSE(a.pdi_active());
}

TEST(EscEeprom, ABadChecksumLeavesThePdiOffAndFlagsTheError) {
    auto image = eeprom_image(0x05, 0x00, 0x0042);
    image[14] ^= 0x5A;
    esc::Esc a(image);
    EXPECT_FALSE(a.eeprom_loaded());
    EXPECT_FALSE(a.pdi_active());
    EXPECT_EQ(a.peek8(ethercat::reg::pdi_control), 0);
    EXPECT_EQ(a.peek16(ethercat::reg::station_alias), 0);
    EXPECT_EQ(a.peek16(ethercat::reg::eeprom_control) & (ethercat::reg::eeprom_checksum_error | ethercat::reg::eeprom_not_loaded),
              ethercat::reg::eeprom_checksum_error | ethercat::reg::eeprom_not_loaded);
    FrameBuilder f;
    f.add(Command::aprd, 0, ethercat::reg::dl_status, {0, 0});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.data(payload, 0)[0] & ethercat::reg::dl_status_pdi_operational, 0);
}

TEST(EscEeprom, ATruncatedImageFailsTheChecksum) {
    auto image = eeprom_image(0x05);
    image.resize(10);
    esc::Esc a(image);
    EXPECT_FALSE(a.eeprom_loaded());
    EXPECT_TRUE(a.peek16(ethercat::reg::eeprom_control) & ethercat::reg::eeprom_checksum_error);
}

TEST(EscEeprom, ReadCommandReturnsEightBytesFromTheWordAddress) {
    esc::Esc a(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::apwr, 0, ethercat::reg::eeprom_control, {0x00, 0x01, 0x08, 0x00, 0x00, 0x00});  // read word 8
    f.add(Command::aprd, 0, ethercat::reg::eeprom_control, {0, 0});
    f.add(Command::aprd, 0, ethercat::reg::eeprom_data, std::vector<std::uint8_t>(8, 0));
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    const auto status = f.data(payload, 1);
    EXPECT_EQ(status[1] & 0x87, 0);     // not busy, no command pending
    EXPECT_TRUE(status[0] & 0x40);      // 8-byte reads
    EXPECT_EQ(f.data(payload, 2), (std::vector<std::uint8_t>{0x9A, 0, 0, 0, 0x34, 0x12, 0, 0}));
}

TEST(EscEeprom, ReadsPastTheImageAreErased) {
    esc::Esc a(eeprom_image(0x05));
    FrameBuilder f;
    f.add(Command::apwr, 0, ethercat::reg::eeprom_control, {0x00, 0x01, 0xFF, 0x7F, 0x00, 0x00});
    f.add(Command::aprd, 0, ethercat::reg::eeprom_data, std::vector<std::uint8_t>(4, 0));
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_EQ(f.data(payload, 1), (std::vector<std::uint8_t>(4, 0xFF)));
}

TEST(EscEeprom, WriteNeedsWriteEnableAndChangesTheImageInMemory) {
    esc::Esc a(eeprom_image(0x05));
    FrameBuilder refused;
    refused.add(Command::apwr, 0, ethercat::reg::eeprom_data, {0xCD, 0xAB});
    refused.add(Command::apwr, 0, ethercat::reg::eeprom_control, {0x00, 0x02, 0x40, 0x00, 0x00, 0x00});
    auto payload = refused.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_TRUE(a.peek16(ethercat::reg::eeprom_control) & ethercat::reg::eeprom_write_error);
    EXPECT_EQ(a.eeprom()[0x80], 0xFF);

    FrameBuilder accepted;
    accepted.add(Command::apwr, 0, ethercat::reg::eeprom_control, {0x01, 0x02, 0x40, 0x00, 0x00, 0x00});
    payload = accepted.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_FALSE(a.peek16(ethercat::reg::eeprom_control) & ethercat::reg::eeprom_write_error);
    EXPECT_EQ(a.eeprom()[0x80], 0xCD);
    EXPECT_EQ(a.eeprom()[0x81], 0xAB);
}

TEST(EscEeprom, ReloadAppliesAWrittenConfigurationArea) {
    esc::Esc a(eeprom_image(0x00));
    ASSERT_FALSE(a.pdi_active());
    auto image = eeprom_image(0x05);
    FrameBuilder f;
    for (std::uint16_t word : {0, 7}) {
        f.add(Command::apwr, 0, ethercat::reg::eeprom_data,
              {image[word * 2u], image[word * 2u + 1]});
        f.add(Command::apwr, 0, ethercat::reg::eeprom_control,
              {0x01, 0x02, static_cast<std::uint8_t>(word), 0x00, 0x00, 0x00});
    }
    f.add(Command::apwr, 0, ethercat::reg::eeprom_control, {0x00, 0x04});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}), esc::FrameOutcome::answered);
    EXPECT_TRUE(a.pdi_active());
    EXPECT_EQ(a.peek8(ethercat::reg::pdi_control), 0x05);
}

}  // namespace
}  // namespace esi::test
