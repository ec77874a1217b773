// SOEM 2.x reads every object each sample's SDO Information lists, sub-index by sub-index, through
// esi-sim in PREOP, and gets the model's default values.

#include <gtest/gtest.h>

#include "sim/coe_dictionary_build.hpp"
#include "sim_esc/sim_fixtures.hpp"
#include "sim_esc/soem_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

std::string hex(const std::vector<std::uint8_t>& bytes) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (std::uint8_t b : bytes) {
        out += digits[b >> 4];
        out += digits[b & 15];
    }
    return out;
}

TEST(SoemSdo, EveryListedObjectReadsItsDefault) {
    ESI_REQUIRE_SOEM();
    TempDir dir;
    std::vector<ModelDevice> devices;
    // Not servo-item-c-series.yaml: SOEM 2.x's ecx_readODlist crashes on its dictionary (a NULL
    // mailbox buffer in ecx_mbxreceive, not yet analysed); the servo's OP run is in
    // soem_samples_test.cpp.
    for (const char* f : {"digital-io-8.yaml", "encoder-tr-linear.yaml", "inverter-stoeber-mds5000.yaml"})
        for (ModelDevice& d : model_devices(source_dir() / "samples" / f)) devices.push_back(std::move(d));
    std::vector<SoemStep> steps;
    for (const ModelDevice& d : devices) {
        std::vector<std::string> args = {d.file.string(), "--device", d.selector()};
        if (d.image[0] == 0) {
            const auto path = dir / (d.file.stem().string() + ".bin");
            write_bytes(path, with_config_word0(d.image, 0x05, d.image[1]));
            args.insert(args.end(), {"--eeprom", path.string()});
        }
        steps.push_back({args, {"--cycles", "1", "--sdo", "--state-timeout-ms", "3000"}});
    }
    const auto results = run_soem_session(steps);
    ASSERT_EQ(results.size(), devices.size());
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const ModelDevice& d = devices[i];
        SCOPED_TRACE(d.device->type.text);
        ASSERT_TRUE(results[i].report) << results[i].sim_stderr << results[i].master_output;
        const auto& r = *results[i].report;
        Diagnostics diagnostics;
        const sim::DeviceModel model = sim::build_device_model(*d.info, *d.device, diagnostics);
        std::size_t compared = 0;
        for (const auto& read : r["sdo"]) {
            const std::uint32_t index = read["index"];
            const std::uint32_t sub = read["sub"];
            const sim::CoeObject* object = model.dictionary.find(index);
            ASSERT_NE(object, nullptr) << "SDO Information lists 0x" << std::hex << index << ", the model has no such object";
            const sim::CoeEntry* entry = object->entry(sub);
            if (!entry || !entry->readable_somewhere()) continue;
            EXPECT_TRUE(read["ok"].get<bool>()) << std::hex << "0x" << index << ":" << sub;
            if (!read["ok"].get<bool>()) continue;
            EXPECT_EQ(read["value"].get<std::string>(), hex(entry->default_value)) << std::hex << "0x" << index << ":" << sub;
            ++compared;
        }
        EXPECT_GT(compared, 5u) << "SOEM read too few objects: " << results[i].master_output.substr(0, 400);
    }
}

}  // namespace
}  // namespace esi::test
