// Each sample device as SOES firmware on the emulated ESC (issue 21): esi-gen's SOES set built
// with the real SOES core and the HAL of firmware/, esi-gen's EEPROM image for the same source in
// the ESC, and SOEM 2.x on the other end of a veth pair. SOEM reaches OP, reads the model's PDO
// assignment over CoE, runs 1,000 cycles with the expected working counter, and every variable
// of esi-net's process_image.json carries the same bits at the master and in SOES's objects.

#include <gtest/gtest.h>

#include <map>

#include "sim_soes/soes_fixtures.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

namespace fs = std::filesystem;

// Every sample's firmware (cc of the SOES core per sample, once per run).
std::vector<SoesFirmware> sample_firmware() {
    std::vector<fs::path> sources;
    for (const auto& e : fs::directory_iterator(source_dir() / "samples"))
        if (e.path().extension() == ".yaml") sources.push_back(e.path());
    std::sort(sources.begin(), sources.end());
    std::vector<SoesFirmware> out;
    for (const fs::path& s : sources) out.push_back(soes_firmware(s));
    return out;
}

std::vector<std::string> host_args(const SoesFirmware& fw) {
    return {fw.source.string(), "--eeprom", fw.eeprom.string(), "--firmware", fw.library.string()};
}

TEST(SoesSamples, EverySampleReachesOpAndItsProcessImageMatchesBitForBit) {
    ESI_REQUIRE_SOES_ON_SIM();
    const std::vector<SoesFirmware> firmware = sample_firmware();
    ASSERT_GE(firmware.size(), 5u);
    std::vector<SoesStep> steps;
    for (const SoesFirmware& fw : firmware) {
        ASSERT_EQ(fw.error, "") << fw.source;
        steps.push_back({host_args(fw), {"--cycles", "1000", "--state-timeout-ms", "3000"}, {}, false});
    }
    const auto results = run_soes_session(steps);
    ASSERT_EQ(results.size(), firmware.size());
    for (std::size_t i = 0; i < results.size(); ++i) {
        const SoesFirmware& fw = firmware[i];
        const SoesStepResult& r = results[i];
        SCOPED_TRACE(fw.source.filename().string() + " " + fw.type);
        ASSERT_TRUE(r.master) << r.host_stderr << r.master_output;
        ASSERT_TRUE(r.host) << r.host_stderr << r.host_output;
        EXPECT_EQ(r.host_exit, 0) << r.host_stderr;
        const auto& m = *r.master;
        ASSERT_EQ(m["slaves"], 1);
        const auto& s = m["slave"][0];
        ASSERT_EQ(m["op"], true) << "state " << s["state"] << ", AL status code " << s["al_status_code"];
        ASSERT_EQ(r.host->size(), 1u);
        const auto& h = (*r.host)[0];
        EXPECT_EQ(h["al_status"], 1) << "SOES back in INIT after the master left";
        EXPECT_GE(h["op_polls"], 1000);

        // The PDO assignment and mapping SOEM reads over CoE are the model's.
        EXPECT_EQ(s["assign"], fw.default_assign);
        // esi-net's image: the slave's sizes and the working counter SOEM expects of them.
        const auto& slave = fw.process_image["slaves"][0];
        EXPECT_EQ(m["obytes"], slave["output_bytes"]);
        EXPECT_EQ(m["ibytes"], slave["input_bytes"]);
        // SOEM 2.x also reads each mailbox slave's SM1 status in the same frame (after the
        // process data); a slave without inputs adds 1 to the working counter for it.
        const bool inputs = slave["input_bytes"] > 0;
        const int wkc = (slave["output_bytes"] > 0 ? 2 : 0) + (inputs ? 1 : 0) + (inputs ? 0 : 1);
        EXPECT_EQ(m["expected_wkc"], wkc);
        EXPECT_EQ(m["cycles"], 1000);
        EXPECT_EQ(m["wkc_ok"], 1000);
        expect_variables_match(fw.process_image, 0, m, h);
    }
}

}  // namespace
}  // namespace esi::test
