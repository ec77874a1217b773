// The samples' dictionaries read over CoE through the emulated ESC's mailbox, frame by frame, in
// SAFEOP (before process data has changed any object): SDO Information lists the model's objects
// with their descriptions, and every sub-index readable in SAFEOP uploads its default
// (expedited, normal or segmented as its size asks).

#include <gtest/gtest.h>

#include "sim/coe_dictionary_build.hpp"
#include "sim_esc/line_master.hpp"
#include "sim_esc/line_session.hpp"
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

// The master with `d` in SAFEOP (mailbox, PREOP, process data, SAFEOP).
bool to_safeop(LineMaster& master) {
    if (!master.scan() || !master.setup_mailbox(master.slaves[0])) return false;
    if (master.request_state(master.slaves[0], 2).state() != 2) return false;
    master.setup_process_data();
    return master.request_state(master.slaves[0], 4).state() == 4;
}

TEST(LineSdo, EveryObjectOfEverySampleUploadsItsDefaultAndSdoInformationListsTheModel) {
    TempDir dir;
    // The servo declares no SDO Information (sdo_info: false); a copy that declares it shows its
    // whole dictionary through SDO Information too.
    const auto servo_with_info = dir / "servo-with-sdo-info.yaml";
    std::string servo = read_text(source_dir() / "samples" / "servo-item-c-series.yaml");
    const auto flag = servo.find("sdo_info: false");
    ASSERT_NE(flag, std::string::npos);
    servo.replace(flag, 15, "sdo_info: true");
    write_text(servo_with_info, servo);
    std::vector<std::filesystem::path> files;
    for (const char* f : {"digital-io-8.yaml", "encoder-tr-linear.yaml", "inverter-stoeber-mds5000.yaml", "modular-coupler.yaml"})
        files.push_back(source_dir() / "samples" / f);
    files.push_back(servo_with_info);
    for (const auto& file : files) {
        for (const ModelDevice& d : model_devices(file)) {
            SCOPED_TRACE(file.filename().string() + " " + d.device->type.text);
            std::string error;
            std::optional<sim::Line> line = device_line(d, runnable_image(d), false, error);
            ASSERT_TRUE(line) << error;
            LineMaster master(*line);
            ASSERT_TRUE(to_safeop(master));
            LineSlave& s = master.slaves[0];
            const sii::General* general = s.decoded.image.general();
            ASSERT_NE(general, nullptr);
            EXPECT_NE(general->coe_details & 0x02, 0) << "SDO Information not in the SII's CoE details";

            Diagnostics diagnostics;
            const sim::DeviceModel model = sim::build_device_model(*d.info, *d.device, diagnostics);
            std::string failure;
            const auto listed = master.od_list(s, failure);
            ASSERT_TRUE(listed) << failure;
            std::vector<std::uint16_t> model_indices;
            for (const sim::CoeObject& o : model.dictionary.objects()) model_indices.push_back(o.index);
            EXPECT_EQ(*listed, model_indices) << "the OD list is not the model's dictionary";

            std::size_t compared = 0;
            for (const sim::CoeObject& object : model.dictionary.objects()) {
                SCOPED_TRACE(testing::Message() << "object 0x" << std::hex << object.index);
                const auto description = master.object_description(s, object.index, failure);
                ASSERT_TRUE(description) << failure;
                EXPECT_EQ(description->index, object.index);
                EXPECT_EQ(description->data_type, object.data_type);
                EXPECT_EQ(description->object_code, object.code);
                EXPECT_EQ(description->max_subindex, object.max_subindex());
                EXPECT_EQ(description->name, object.name);
                for (const sim::CoeEntry& entry : object.entries) {
                    if (!entry.readable(sim::AlState::safeop)) continue;
                    const SdoUpload read = master.upload(s, object.index, entry.subindex);
                    ASSERT_TRUE(read.ok()) << "sub-index " << unsigned(entry.subindex) << ": abort 0x" << std::hex << read.abort_code << " "
                                           << read.failure;
                    EXPECT_EQ(hex(read.data), hex(entry.default_value)) << "sub-index " << unsigned(entry.subindex);
                    ++compared;
                }
            }
            EXPECT_GT(compared, 5u);
            // Every transfer left the device where it was.
            EXPECT_EQ(master.state_of(s).al_status, 4);
        }
    }
}

TEST(LineSdo, AnObjectThatDoesNotExistIsAbortedWithItsCode) {
    SampleLine sample = sample_line("digital-io-8.yaml", false);
    ASSERT_TRUE(sample.line) << sample.error;
    LineMaster master(*sample.line);
    ASSERT_TRUE(to_safeop(master));
    const SdoUpload missing = master.upload(master.slaves[0], 0x5FFE, 0);
    EXPECT_TRUE(missing.failure.empty()) << missing.failure;
    EXPECT_EQ(missing.abort_code, 0x06020000u);  // "object does not exist" (ETG.1000.6 Table 41)
    const SdoUpload sub = master.upload(master.slaves[0], 0x1018, 0x7F);
    EXPECT_EQ(sub.abort_code, 0x06090011u);  // "sub-index does not exist"
}

// A device without SDO Information says so in its SII (the CoE details' bit 1 clear), so a
// master does not ask; asked anyway, it answers with an error, never with a list.
TEST(LineSdo, ADeviceWithoutSdoInformationSaysSoAndRefusesTheOdList) {
    SampleLine sample = sample_line("servo-item-c-series.yaml", false);
    ASSERT_TRUE(sample.line) << sample.error;
    LineMaster master(*sample.line);
    ASSERT_TRUE(to_safeop(master));
    const sii::General* general = master.slaves[0].decoded.image.general();
    ASSERT_NE(general, nullptr);
    EXPECT_EQ(general->coe_details & 0x02, 0);
    std::string failure;
    EXPECT_FALSE(master.od_list(master.slaves[0], failure));
    EXPECT_NE(failure.find("error"), std::string::npos) << failure;
    // The mailbox keeps working after the refusal.
    EXPECT_TRUE(master.upload(master.slaves[0], 0x1018, 1).ok());
}

}  // namespace
}  // namespace esi::test

namespace esi::test {
namespace {

// A master reads 0x1C00 and then 0x1C10+n for every process-data SM it lists (SOEM, KickCAT):
// each of those assignment objects exists, with no PDO assigned where the device has none for
// that SM (issue 37, F14: the encoder and modular-coupler samples had no 0x1C12).
TEST(LineSdo, EverySmTheSmTypesObjectListsAsProcessDataHasItsAssignmentObject) {
    std::size_t checked = 0;
    for (const ModelDevice& d : sample_devices()) {
        SCOPED_TRACE(d.file.filename().string() + " " + d.device->type.text);
        std::string error;
        std::optional<sim::Line> line = device_line(d, runnable_image(d), false, error);
        ASSERT_TRUE(line) << error;
        LineMaster master(*line);
        ASSERT_TRUE(master.scan());
        LineSlave& s = master.slaves[0];
        ASSERT_TRUE(master.setup_mailbox(s));
        ASSERT_EQ(master.request_state(s, 2).state(), 2);
        const SdoUpload count = master.upload(s, 0x1C00, 0);
        ASSERT_TRUE(count.ok() && !count.data.empty()) << "0x1C00:00 abort 0x" << std::hex << count.abort_code << count.failure;
        for (unsigned n = 1; n <= count.data[0]; ++n) {
            const SdoUpload type = master.upload(s, 0x1C00, static_cast<std::uint8_t>(n));
            ASSERT_TRUE(type.ok() && !type.data.empty());
            if (type.data[0] != 3 && type.data[0] != 4) continue;
            const auto index = static_cast<std::uint16_t>(0x1C10 + n - 1);
            const SdoUpload assigned = master.upload(s, index, 0);
            EXPECT_TRUE(assigned.ok()) << "0x" << std::hex << index << ":00 abort 0x" << assigned.abort_code << assigned.failure;
            ++checked;
        }
    }
    EXPECT_GE(checked, 10u);
}

}  // namespace
}  // namespace esi::test
