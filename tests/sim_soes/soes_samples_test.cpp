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

// The firmware of every sample, built once for the suite (cc of the SOES core per sample).
class SoesSamples : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!soes_unavailable().empty()) return;
        work_ = new TempDir;
        firmware_ = new std::vector<SoesFirmware>;
        std::vector<fs::path> sources;
        for (const auto& e : fs::directory_iterator(source_dir() / "samples"))
            if (e.path().extension() == ".yaml") sources.push_back(e.path());
        std::sort(sources.begin(), sources.end());
        for (const fs::path& s : sources) firmware_->push_back(build_soes_firmware(s, work_->path()));
    }
    static void TearDownTestSuite() {
        delete firmware_;
        delete work_;
        firmware_ = nullptr;
        work_ = nullptr;
    }
    static TempDir* work_;
    static std::vector<SoesFirmware>* firmware_;
};
TempDir* SoesSamples::work_ = nullptr;
std::vector<SoesFirmware>* SoesSamples::firmware_ = nullptr;

std::vector<std::string> host_args(const SoesFirmware& fw) {
    return {fw.source.string(), "--eeprom", fw.eeprom.string(), "--firmware", fw.library.string()};
}

std::uint64_t hex_number(const nlohmann::json& v) { return std::stoull(v.get<std::string>(), nullptr, 16); }

// The host's objects by index:sub-index.
std::map<std::pair<std::uint64_t, std::uint64_t>, nlohmann::json> objects(const nlohmann::json& list) {
    std::map<std::pair<std::uint64_t, std::uint64_t>, nlohmann::json> out;
    for (const auto& o : list) out[{o["index"].get<std::uint64_t>(), o["sub"].get<std::uint64_t>()}] = o;
    return out;
}

// Every variable of the process image: the bits the master holds at its offset equal the value
// of the object in SOES (outputs: what SOES received last in OP; inputs: what the host set).
void expect_variables_match(const SoesFirmware& fw, const nlohmann::json& master, const nlohmann::json& host) {
    const auto outputs = objects(host["outputs"]);
    const auto inputs = objects(host["inputs"]);
    int checked = 0;
    for (const auto& v : fw.process_image["variables"]) {
        SCOPED_TRACE(v["name"].get<std::string>());
        const bool output = v["direction"] == "output";
        const auto& found = output ? outputs : inputs;
        const auto it = found.find({hex_number(v["index"]), hex_number(v["subindex"])});
        ASSERT_NE(it, found.end()) << "SOES has no object for the variable";
        ASSERT_TRUE(it->second.contains("value")) << "SOES never received outputs in OP";
        const auto offset = v["byte_offset"].get<std::uint32_t>() * 8 + v["bit_offset"].get<std::uint32_t>();
        const auto bits = v["bit_size"].get<std::uint32_t>();
        const std::string& image = master[output ? "outputs" : "inputs"].get_ref<const std::string&>();
        ASSERT_LE((offset + bits + 7) / 8, image.size() / 2) << "the variable lies past the master's image";
        EXPECT_EQ(image_bits(image, offset, bits), it->second["value"].get<std::uint64_t>())
            << "at bit " << offset << ", " << bits << " bits";
        ++checked;
    }
    // Only a device without process data (the modular coupler, whose modules the SOES set does
    // not hold) has nothing to check.
    const auto& slave = fw.process_image["slaves"][0];
    if (slave["output_bytes"] > 0 || slave["input_bytes"] > 0) {
        EXPECT_GT(checked, 0);
    }
}

TEST_F(SoesSamples, EverySampleReachesOpAndItsProcessImageMatchesBitForBit) {
    ESI_REQUIRE_SOES_ON_SIM();
    ASSERT_GE(firmware_->size(), 5u);
    std::vector<SoesStep> steps;
    for (const SoesFirmware& fw : *firmware_) {
        ASSERT_EQ(fw.error, "") << fw.source;
        steps.push_back({host_args(fw), {"--cycles", "1000", "--state-timeout-ms", "3000"}, {}, false});
    }
    const auto results = run_soes_session(steps);
    ASSERT_EQ(results.size(), firmware_->size());
    for (std::size_t i = 0; i < results.size(); ++i) {
        const SoesFirmware& fw = (*firmware_)[i];
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
        expect_variables_match(fw, m, h);
    }
}

}  // namespace
}  // namespace esi::test
