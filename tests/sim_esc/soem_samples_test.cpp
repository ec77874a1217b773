// SOEM 2.x against esi-sim: the samples scanned, the EEPROM faults a real ESC shows, and OP.

#include <gtest/gtest.h>

#include "sim_esc/sim_fixtures.hpp"
#include "sim_esc/soem_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

std::vector<ModelDevice> sample_devices() {
    std::vector<ModelDevice> out;
    for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "samples"))
        if (entry.path().extension() == ".yaml")
            for (ModelDevice& d : model_devices(entry.path())) out.push_back(std::move(d));
    std::sort(out.begin(), out.end(), [](const ModelDevice& a, const ModelDevice& b) { return a.file < b.file; });
    return out;
}

std::vector<std::string> source_args(const ModelDevice& d) {
    return {d.file.string(), "--device", d.selector()};
}

TEST(SoemSamples, ScanFindsOneSlaveWithTheModelsIdentityAndName) {
    ESI_REQUIRE_SOEM();
    const std::vector<ModelDevice> devices = sample_devices();
    ASSERT_GE(devices.size(), 5u);
    std::vector<SoemStep> steps;
    for (const ModelDevice& d : devices) steps.push_back({source_args(d), {"--scan-only"}});
    const auto results = run_soem_session(steps);
    ASSERT_EQ(results.size(), devices.size());
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const ModelDevice& d = devices[i];
        SCOPED_TRACE(d.file.filename().string() + " " + d.device->type.text);
        ASSERT_TRUE(results[i].report) << results[i].sim_stderr << results[i].master_output;
        const auto& r = *results[i].report;
        EXPECT_NE(results[i].sim_stderr.find("esi-sim: 1 slave(s) on v1"), std::string::npos) << results[i].sim_stderr;
        EXPECT_EQ(results[i].sim_exit, 0);
        ASSERT_EQ(r["slaves"], 1);
        const auto& s = r["slave"][0];
        EXPECT_EQ(s["vendor"], d.vendor_id);
        EXPECT_EQ(s["product"], d.product_code);
        EXPECT_EQ(s["revision"], d.revision);
        // SOEM names a slave with the first SII string, which the image builder makes the Type text.
        EXPECT_EQ(s["name"], d.device->type.text.substr(0, 40));
        EXPECT_EQ(s["eeprom_checksum_error"], false);
        EXPECT_EQ(s["pdi_operational"], true);
    }
}

TEST(SoemSamples, CorruptedEepromShowsTheChecksumErrorAndNoPdi) {
    ESI_REQUIRE_SOEM();
    const std::vector<ModelDevice> devices = model_devices(source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_EQ(devices.size(), 1u);
    TempDir dir;
    auto bad_crc = devices[0].image;
    bad_crc[14] ^= 0xA5;
    write_bytes(dir / "bad-crc.bin", bad_crc);
    auto truncated = devices[0].image;
    truncated.resize(12);
    write_bytes(dir / "truncated.bin", truncated);
    const auto results = run_soem_session({
        {{devices[0].file.string(), "--eeprom", (dir / "bad-crc.bin").string()}, {"--cycles", "5", "--state-timeout-ms", "300"}},
        {{devices[0].file.string(), "--eeprom", (dir / "truncated.bin").string()}, {"--scan-only"}},
    });
    ASSERT_EQ(results.size(), 2u);
    for (const auto& result : results) {
        ASSERT_TRUE(result.report) << result.sim_stderr << result.master_output;
        const auto& s = (*result.report)["slave"][0];
        EXPECT_EQ(s["eeprom_checksum_error"], true);
        EXPECT_EQ(s["eeprom_not_loaded"], true);
        EXPECT_EQ(s["pdi_operational"], false);
        EXPECT_NE(s["state"], 8);
    }
    // The bad checksum leaves the rest of the image readable: SOEM still reads the identity.
    EXPECT_EQ((*results[0].report)["slave"][0]["product"], devices[0].product_code);
    EXPECT_EQ((*results[0].report)["op"], false);
}

TEST(SoemSamples, APdiOffImageDoesNotReachOp) {
    ESI_REQUIRE_SOEM();
    const std::vector<ModelDevice> devices = model_devices(source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_EQ(devices.size(), 1u);
    TempDir dir;
    write_bytes(dir / "pdi-off.bin", with_config_word0(devices[0].image, 0x00, 0x00));
    const auto results =
        run_soem_session({{{devices[0].file.string(), "--eeprom", (dir / "pdi-off.bin").string()},
                                 {"--cycles", "5", "--state-timeout-ms", "300"}}});
    ASSERT_TRUE(results[0].report) << results[0].sim_stderr << results[0].master_output;
    const auto& r = *results[0].report;
    EXPECT_EQ(r["op"], false);
    EXPECT_EQ(r["slave"][0]["state"], 1);  // no firmware ever answers: INIT
    EXPECT_EQ(r["slave"][0]["pdi_operational"], true);
}

TEST(SoemSamples, DeviceEmulationReachesOpAndRunsAThousandCycles) {
    ESI_REQUIRE_SOEM();
    // ESC configuration bit 0: the ESC itself answers the AL state machine (a terminal without a
    // microcontroller), so this shows the ESC alone carries SOEM's whole start-up and cycle.
    const std::vector<ModelDevice> devices = model_devices(source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_EQ(devices.size(), 1u);
    TempDir dir;
    write_bytes(dir / "emulated.bin", with_config_word0(devices[0].image, 0x00, 0x01));
    const auto results =
        run_soem_session({{{devices[0].file.string(), "--eeprom", (dir / "emulated.bin").string()}, {"--cycles", "1000"}}});
    ASSERT_TRUE(results[0].report) << results[0].sim_stderr << results[0].master_output;
    const auto& r = *results[0].report;
    EXPECT_EQ(r["op"], true);
    EXPECT_EQ(r["expected_wkc"], 3);
    EXPECT_EQ(r["cycles"], 1000);
    EXPECT_EQ(r["wkc_ok"], 1000);
    EXPECT_EQ(r["slave"][0]["obits"], devices[0].output_bits);
    EXPECT_EQ(r["slave"][0]["ibits"], devices[0].input_bits);
}

}  // namespace
}  // namespace esi::test

namespace esi::test {
namespace {

// Samples whose ConfigData has no PDI (PDI control 0) run from an image that enables one (SPI),
// with the checksum made right: the firmware needs an interface to its ESC.
std::vector<std::string> runnable_source_args(const ModelDevice& d, const TempDir& dir) {
    std::vector<std::string> args = source_args(d);
    if (d.image[0] == 0) {
        const auto path = dir / (d.file.stem().string() + "-" + d.selector() + ".bin");
        write_bytes(path, with_config_word0(d.image, 0x05, d.image[1]));
        args.insert(args.end(), {"--eeprom", path.string()});
    }
    return args;
}

TEST(SoemSamples, EverySampleReachesOpRunsAThousandCyclesAndEchoesItsOutputs) {
    ESI_REQUIRE_SOEM();
    const std::vector<ModelDevice> devices = sample_devices();
    TempDir dir;
    std::vector<SoemStep> steps;
    for (const ModelDevice& d : devices) {
        std::vector<std::string> args = runnable_source_args(d, dir);
        args.push_back("--echo");
        steps.push_back({args, {"--cycles", "1000", "--echo", "--state-timeout-ms", "3000"}});
    }
    const auto results = run_soem_session(steps);
    ASSERT_EQ(results.size(), devices.size());
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const ModelDevice& d = devices[i];
        SCOPED_TRACE(d.file.filename().string() + " " + d.device->type.text);
        ASSERT_TRUE(results[i].report) << results[i].sim_stderr << results[i].master_output;
        const auto& r = *results[i].report;
        const auto& s = r["slave"][0];
        EXPECT_EQ(r["op"], true) << "state " << s["state"] << ", AL status code " << s["al_status_code"] << " "
                                 << s["al_status_text"];
        EXPECT_EQ(s["obits"], d.output_bits);
        EXPECT_EQ(s["ibits"], d.input_bits);
        EXPECT_EQ(r["cycles"], 1000);
        EXPECT_EQ(r["wkc_ok"], 1000) << "expected working counter " << r["expected_wkc"];
        EXPECT_EQ(r["echo_ok"], r["echo_checked"]);
    }
}

}  // namespace
}  // namespace esi::test
