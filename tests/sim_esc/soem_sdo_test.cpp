// SOEM 2.x reads each sample's dictionary through esi-sim over SDO Information (ecx_readODlist,
// ecx_readODdescription, ecx_readOE) and every object sub-index by sub-index, in SAFEOP: the
// descriptions and the default values are the model's.

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

// The model of a device, and the SOEM step that runs it with --sdo.
struct SdoRun {
    ModelDevice device;
    SoemStep step;
};

SdoRun sdo_run(ModelDevice d, const TempDir& dir) {
    std::vector<std::string> args = {d.file.string(), "--device", d.selector()};
    if (d.image[0] == 0) {
        const auto path = dir / (d.file.stem().string() + ".bin");
        write_bytes(path, with_config_word0(d.image, 0x05, d.image[1]));
        args.insert(args.end(), {"--eeprom", path.string()});
    }
    return {std::move(d), {args, {"--cycles", "1", "--sdo", "--state-timeout-ms", "3000"}}};
}

// What SOEM's ecx_readODlist, ecx_readODdescription and ecx_readOE got equals the model's
// dictionary, object by object and entry by entry, and every readable entry reads its default.
void expect_dictionary_matches(const ModelDevice& d, const nlohmann::json& r, const std::string& master_output) {
    Diagnostics diagnostics;
    const sim::DeviceModel model = sim::build_device_model(*d.info, *d.device, diagnostics);
    std::vector<std::uint32_t> listed;
    for (const auto& o : r["od"]) {
        const std::uint32_t index = o["index"];
        listed.push_back(index);
        const sim::CoeObject* object = model.dictionary.find(index);
        ASSERT_NE(object, nullptr) << "SDO Information lists 0x" << std::hex << index << ", the model has no such object";
        SCOPED_TRACE(testing::Message() << "object 0x" << std::hex << index);
        EXPECT_EQ(o["data_type"], object->data_type);
        EXPECT_EQ(o["object_code"], object->code);
        EXPECT_EQ(o["max_sub"], object->max_subindex());
        for (const auto& e : o["entries"]) {
            const std::uint32_t sub = e["sub"];
            const sim::CoeEntry* entry = object->entry(sub);
            if (!entry) {  // a gap in a RECORD: SOEM's ecx_readOE got the info error, nothing
                EXPECT_EQ(e["bit_length"], 0) << "sub-index " << sub;
                continue;
            }
            EXPECT_EQ(e["data_type"], entry->data_type) << "sub-index " << sub;
            EXPECT_EQ(e["bit_length"], entry->bit_size) << "sub-index " << sub;
            EXPECT_EQ(e["access"], entry->access) << "sub-index " << sub;
        }
    }
    std::vector<std::uint32_t> model_indices;
    for (const sim::CoeObject& o : model.dictionary.objects()) model_indices.push_back(o.index);
    EXPECT_EQ(listed, model_indices) << "the OD list SOEM read is not the model's dictionary";
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
    EXPECT_GT(compared, 5u) << "SOEM read too few objects: " << master_output.substr(0, 400);
}

TEST(SoemSdo, EveryListedObjectReadsItsDefault) {
    ESI_REQUIRE_SOEM();
    TempDir dir;
    // The servo declares no SDO Information (sdo_info: false); a copy that declares it shows its
    // whole dictionary through SOEM's SDO Information calls.
    const auto servo_with_info = dir / "servo-with-sdo-info.yaml";
    std::string servo = read_text(source_dir() / "samples" / "servo-item-c-series.yaml");
    const auto flag = servo.find("sdo_info: false");
    ASSERT_NE(flag, std::string::npos);
    servo.replace(flag, 15, "sdo_info: true");
    write_text(servo_with_info, servo);
    std::vector<std::filesystem::path> files;
    for (const char* f : {"digital-io-8.yaml", "encoder-tr-linear.yaml", "inverter-stoeber-mds5000.yaml"})
        files.push_back(source_dir() / "samples" / f);
    files.push_back(servo_with_info);
    std::vector<SdoRun> runs;
    for (const auto& file : files)
        for (ModelDevice& d : model_devices(file)) runs.push_back(sdo_run(std::move(d), dir));
    ASSERT_EQ(runs.size(), files.size());
    std::vector<SoemStep> steps;
    for (const SdoRun& run : runs) steps.push_back(run.step);
    const auto results = run_soem_session(steps);
    ASSERT_EQ(results.size(), runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i) {
        SCOPED_TRACE(runs[i].device.file.filename().string());
        ASSERT_TRUE(results[i].report) << results[i].sim_stderr << results[i].master_output;
        const auto& r = *results[i].report;
        EXPECT_NE(r["slave"][0]["coe_details"].get<unsigned>() & 0x02, 0u) << "SDO Information not in the SII's CoE details";
        EXPECT_FALSE(r["od"].empty());
        expect_dictionary_matches(runs[i].device, r, results[i].master_output);
    }
}

// A device without SDO Information answers SOEM's ecx_readODlist with the mailbox error "service
// not supported", on which SOEM 2.x's ecx_mbxreceive reads the next mailbox into the buffer it has
// just released (a NULL pointer). The SII tells the master: the servo's CoE details have no SDO
// Information bit, so the test master does not ask, and the session runs to the end.
TEST(SoemSdo, NoSdoInformationDeclaredNoneAsked) {
    ESI_REQUIRE_SOEM();
    TempDir dir;
    auto devices = model_devices(source_dir() / "samples" / "servo-item-c-series.yaml");
    ASSERT_EQ(devices.size(), 1u);
    const SdoRun run = sdo_run(std::move(devices[0]), dir);
    const auto results = run_soem_session({run.step});
    ASSERT_EQ(results.size(), 1u);
    ASSERT_TRUE(results[0].report) << results[0].sim_stderr << results[0].master_output;
    const auto& r = *results[0].report;
    EXPECT_EQ(r["slave"][0]["coe_details"].get<unsigned>() & 0x02, 0u);
    EXPECT_TRUE(r["od"].empty());
    EXPECT_TRUE(r["sdo"].empty());
    EXPECT_EQ(r["op"], true);
}

}  // namespace
}  // namespace esi::test
