// Every sample on the emulated ESC, driven frame by frame by the tests' master (line_master.hpp)
// as a master on the wire would: identities from the EEPROM through the ESC's EEPROM interface,
// the faults a real ESC shows for a broken EEPROM, the ESC's device emulation, and OP with a
// thousand process-data cycles whose outputs come back as inputs (esi-sim --echo).

#include <gtest/gtest.h>

#include <algorithm>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/line_master.hpp"
#include "sim_esc/line_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

namespace reg = ethercat::reg;

// The output image of cycle `c`: a pattern that differs per cycle and per byte.
std::vector<std::uint8_t> pattern(std::uint32_t bytes, unsigned c) {
    std::vector<std::uint8_t> out(bytes);
    for (std::uint32_t i = 0; i < bytes; ++i) out[i] = static_cast<std::uint8_t>(c * 7 + i * 13 + 1);
    return out;
}

TEST(LineSamples, ScanReadsEachSamplesIdentityAndTypeFromItsEeprom) {
    const std::vector<ModelDevice> devices = sample_devices();
    ASSERT_GE(devices.size(), 5u);
    for (const ModelDevice& d : devices) {
        SCOPED_TRACE(d.file.filename().string() + " " + d.device->type.text);
        std::string error;
        std::optional<sim::Line> line = device_line(d, std::nullopt, false, error);
        ASSERT_TRUE(line) << error;
        LineMaster master(*line);
        ASSERT_TRUE(master.scan());
        ASSERT_EQ(master.slaves.size(), 1u);
        const LineSlave& s = master.slaves[0];
        // Read through 0x0502..0x050F in 2 KiB steps up to the end marker: the image esi-sim was
        // given, erased bytes (0xFF) where a step went past its end.
        EXPECT_TRUE(s.decoded.end_offset) << "no end marker read";
        std::size_t differ = 0;
        for (std::size_t i = 0; i < s.sii.size(); ++i)
            if (s.sii[i] != (i < d.image.size() ? d.image[i] : 0xFF)) ++differ;
        EXPECT_EQ(differ, 0u) << "bytes of the EEPROM read that are not the image esi-sim was given";
        EXPECT_TRUE(s.decoded.crc_ok);
        EXPECT_EQ(s.decoded.image.header.vendor_id, d.vendor_id);
        EXPECT_EQ(s.decoded.image.header.product_code, d.product_code);
        EXPECT_EQ(s.decoded.image.header.revision_no, d.revision);
        const sii::General* general = s.decoded.image.general();
        ASSERT_NE(general, nullptr);
        EXPECT_EQ(s.decoded.image.string_at(general->order_idx), d.device->type.text);
        EXPECT_EQ(s.eeprom_status & (reg::eeprom_checksum_error | reg::eeprom_not_loaded), 0);
        // PDI operational (DL status bit 0) as soon as the configuration area is loaded.
        EXPECT_NE(s.dl_status & reg::dl_status_pdi_operational, 0);
    }
}

TEST(LineSamples, ACorruptedEepromShowsTheChecksumErrorAndNoPdi) {
    const std::vector<ModelDevice> devices = model_devices(source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_EQ(devices.size(), 1u);
    const ModelDevice& d = devices[0];
    auto bad_crc = d.image;
    bad_crc[14] ^= 0xA5;
    auto truncated = d.image;
    truncated.resize(12);
    for (const auto& [name, image] : {std::pair{"bad checksum", bad_crc}, std::pair{"truncated", truncated}}) {
        SCOPED_TRACE(name);
        std::string error;
        std::optional<sim::Line> line = device_line(d, image, false, error);
        ASSERT_TRUE(line) << error;
        LineMaster master(*line);
        ASSERT_TRUE(master.scan());
        const LineSlave& s = master.slaves[0];
        EXPECT_NE(s.eeprom_status & reg::eeprom_checksum_error, 0);
        EXPECT_NE(s.eeprom_status & reg::eeprom_not_loaded, 0);
        EXPECT_EQ(s.dl_status & reg::dl_status_pdi_operational, 0);
        EXPECT_FALSE(master.to_op());
        // No firmware runs without a loaded configuration: nothing ever leaves INIT.
        EXPECT_EQ(master.state_of(master.slaves[0]).state(), 1);
    }
    // A wrong checksum leaves the rest of the image readable: the identity is still there.
    std::string error;
    std::optional<sim::Line> line = device_line(d, bad_crc, false, error);
    ASSERT_TRUE(line) << error;
    LineMaster master(*line);
    ASSERT_TRUE(master.scan());
    EXPECT_EQ(master.slaves[0].decoded.image.header.product_code, d.product_code);
    EXPECT_FALSE(master.slaves[0].decoded.crc_ok);
}

TEST(LineSamples, APdiOffImageStaysInInit) {
    const std::vector<ModelDevice> devices = model_devices(source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_EQ(devices.size(), 1u);
    std::string error;
    std::optional<sim::Line> line = device_line(devices[0], with_config_word0(devices[0].image, 0x00, 0x00), false, error);
    ASSERT_TRUE(line) << error;
    LineMaster master(*line);
    ASSERT_TRUE(master.scan());
    // The configuration loaded (PDI operational), but it names no PDI: no firmware answers.
    EXPECT_NE(master.slaves[0].dl_status & reg::dl_status_pdi_operational, 0);
    EXPECT_FALSE(master.to_op());
    const StateResult r = master.state_of(master.slaves[0]);
    EXPECT_EQ(r.state(), 1);
    EXPECT_FALSE(r.error());
}

TEST(LineSamples, TheEscsDeviceEmulationCarriesTheStartUpAndAThousandCycles) {
    // ESC configuration bit 0: the ESC itself answers the AL state machine (a terminal without a
    // microcontroller), so the ESC alone carries the whole start-up and the cycle.
    const std::vector<ModelDevice> devices = model_devices(source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_EQ(devices.size(), 1u);
    const ModelDevice& d = devices[0];
    std::string error;
    std::optional<sim::Line> line = device_line(d, with_config_word0(d.image, 0x00, 0x01), false, error);
    ASSERT_TRUE(line) << error;
    LineMaster master(*line);
    ASSERT_TRUE(master.scan());
    StateResult refusal;
    ASSERT_TRUE(master.to_op(nullptr, &refusal)) << "AL status 0x" << std::hex << refusal.al_status << ", code 0x" << refusal.al_status_code;
    EXPECT_EQ(master.slaves[0].output_bits, (d.output_bits + 7) / 8 * 8);
    EXPECT_EQ(master.slaves[0].input_bits, (d.input_bits + 7) / 8 * 8);
    unsigned wkc_ok = 0;
    for (unsigned c = 0; c < 1000; ++c) {
        const auto a = master.cycle(pattern(master.output_image_bytes(), c));
        if (a && a->working_counter == 3) ++wkc_ok;
    }
    EXPECT_EQ(wkc_ok, 1000u);
}

TEST(LineSamples, EverySampleReachesOpRunsAThousandCyclesAndEchoesItsOutputs) {
    for (const ModelDevice& d : sample_devices()) {
        SCOPED_TRACE(d.file.filename().string() + " " + d.device->type.text);
        std::string error;
        std::optional<sim::Line> line = device_line(d, runnable_image(d), true, error);
        ASSERT_TRUE(line) << error;
        LineMaster master(*line);
        ASSERT_TRUE(master.scan());
        StateResult refusal;
        ASSERT_TRUE(master.to_op(nullptr, &refusal))
            << "AL status 0x" << std::hex << refusal.al_status << ", code 0x" << refusal.al_status_code;
        const LineSlave& s = master.slaves[0];
        // The sizes the master found (over CoE or from the SII) are the model's default PDOs.
        EXPECT_EQ(s.output_bytes(), (d.output_bits + 7) / 8);
        EXPECT_EQ(s.input_bytes(), (d.input_bits + 7) / 8);
        const std::uint16_t expected = static_cast<std::uint16_t>((s.output_bytes() ? 2 : 0) + (s.input_bytes() ? 1 : 0));
        unsigned wkc_ok = 0, echo_checked = 0, echo_ok = 0;
        const std::uint32_t echoed = std::min(s.output_bytes(), s.input_bytes());
        for (unsigned c = 0; c < 1000; ++c) {
            const auto a = master.cycle(pattern(master.output_image_bytes(), c));
            ASSERT_TRUE(a) << "cycle " << c << ": no answer";
            if (a->working_counter == expected) ++wkc_ok;
            // The inputs of this cycle hold the outputs of the one before (the firmware copies
            // them after the frame).
            if (c == 0 || echoed == 0) continue;
            ++echo_checked;
            const std::vector<std::uint8_t> before = pattern(master.output_image_bytes(), c - 1);
            if (std::equal(before.begin(), before.begin() + echoed, a->data.begin())) ++echo_ok;
        }
        EXPECT_EQ(wkc_ok, 1000u) << "expected working counter " << expected;
        EXPECT_EQ(echo_ok, echo_checked);
        EXPECT_EQ(master.state_of(master.slaves[0]).al_status, 8);
    }
}

}  // namespace
}  // namespace esi::test
