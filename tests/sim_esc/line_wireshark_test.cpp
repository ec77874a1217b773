// The traffic between the tests' master and esi-sim's emulated slaves, as a capture on the
// master's port, read by Wireshark's EtherCAT dissectors (tshark, Debian's package): every frame
// decodes as EtherCAT without a malformed or error mark, in both directions, for every sample
// brought to OP with SDO traffic and cycles and for the sample line; and the CoE transfers
// Wireshark decodes are the ones the master made, with the same index, sub-index and answers.

#include <gtest/gtest.h>

#include <sstream>

#include "sim_esc/line_master.hpp"
#include "sim_esc/line_session.hpp"
#include "sim_esc/wireshark_check.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

void expect_clean_decoding(const LineMaster& master, const std::filesystem::path& pcap) {
    write_pcap(pcap, master.capture);
    const TsharkDecoding d = tshark_decode(pcap);
    ASSERT_EQ(d.exit_code, 0) << d.error;
    EXPECT_EQ(d.frames, master.capture.size());
    EXPECT_EQ(d.ethercat_frames, master.capture.size()) << "frames Wireshark did not take for EtherCAT";
    std::string listed;
    for (std::size_t i = 0; i < d.malformed.size() && i < 10; ++i) listed += d.malformed[i] + "\n";
    EXPECT_TRUE(d.malformed.empty()) << d.malformed.size() << " frames marked malformed or in error:\n" << listed;
}

TEST(LineWireshark, EverySamplesStartUpSdoTrafficAndCyclesDecodeCleanly) {
    ESI_REQUIRE_TSHARK();
    TempDir dir;
    for (const ModelDevice& d : sample_devices()) {
        SCOPED_TRACE(d.file.filename().string() + " " + d.device->type.text);
        std::string error;
        std::optional<sim::Line> line = device_line(d, runnable_image(d), true, error);
        ASSERT_TRUE(line) << error;
        LineMaster master(*line);
        ASSERT_TRUE(master.scan());
        ASSERT_TRUE(master.to_op());
        // Expedited, normal and aborted uploads, and some cycles.
        for (std::uint16_t index : {0x1000, 0x1008, 0x1018, 0x1C00, 0x5FFE}) master.upload(master.slaves[0], index, 0);
        for (int c = 0; c < 20; ++c) master.cycle(std::vector<std::uint8_t>(master.output_image_bytes(), static_cast<std::uint8_t>(c)));
        expect_clean_decoding(master, dir / (d.file.stem().string() + ".pcap"));
    }
}

TEST(LineWireshark, TheSampleLineDecodesCleanly) {
    ESI_REQUIRE_TSHARK();
    std::string error;
    std::optional<sim::Line> line = network_line(source_dir() / "samples" / "networks" / "line.yaml", true, error);
    ASSERT_TRUE(line) << error;
    LineMaster master(*line);
    ASSERT_TRUE(master.scan());
    ASSERT_TRUE(master.to_op());
    std::vector<std::string> ours;
    for (int c = 0; c < 20; ++c) {
        const auto a = master.cycle(std::vector<std::uint8_t>(master.output_image_bytes(), static_cast<std::uint8_t>(c)));
        ASSERT_TRUE(a);
        ours.push_back(std::to_string(a->working_counter));
    }
    TempDir dir;
    expect_clean_decoding(master, dir / "line.pcap");
    // The cyclic frames as they came back (LRW, working counter no longer 0): Wireshark reads
    // the working counter the master read, for the last 20 (those after the start-up's).
    std::vector<std::string> theirs = tshark_fields(dir / "line.pcap", "ecat.cmd == 12 && ecat.cnt != 0", {"ecat.cnt"});
    ASSERT_GE(theirs.size(), ours.size());
    theirs.erase(theirs.begin(), theirs.end() - static_cast<std::ptrdiff_t>(ours.size()));
    EXPECT_EQ(theirs, ours);
}

TEST(LineWireshark, TheCoeTransfersWiresharkDecodesAreTheOnesTheMasterMade) {
    ESI_REQUIRE_TSHARK();
    SampleLine sample = sample_line("encoder-tr-linear.yaml", false);
    ASSERT_TRUE(sample.line) << sample.error;
    LineMaster master(*sample.line);
    ASSERT_TRUE(master.scan());
    ASSERT_TRUE(master.setup_mailbox(master.slaves[0]));
    ASSERT_EQ(master.request_state(master.slaves[0], 2).state(), 2);
    master.capture.clear();
    // Each upload is one request and (for these) one answer: expedited ones and three aborts (the
    // encoder has no 0x1008, nobody has 0x5FFE, 0x1018 has no sub-index 0x7F).
    const std::vector<std::pair<std::uint16_t, std::uint8_t>> asked = {{0x1000, 0}, {0x1018, 1}, {0x1018, 2}, {0x1008, 0}, {0x5FFE, 0}, {0x1018, 0x7F}};
    std::vector<std::string> ours;
    for (const auto& [index, sub] : asked) {
        const SdoUpload r = master.upload(master.slaves[0], index, sub);
        ASSERT_TRUE(r.failure.empty()) << r.failure;
        std::ostringstream line_text;
        line_text << index << "\t" << unsigned(sub) << "\t" << (r.abort_code ? std::to_string(r.abort_code) : "");
        ours.push_back(line_text.str());
    }
    TempDir dir;
    write_pcap(dir / "sdo.pcap", master.capture);
    // Initiate-upload requests (CCS 2) as the master sent them into SM0 (FPWR, working counter
    // still 0), with Wireshark's index and sub-index; the answers read from SM1 (FPRD as it came
    // back, working counter 1) with an abort code where there is one.
    const auto requests = tshark_fields(dir / "sdo.pcap", "ecat_mailbox.coe.sdoccsiu && ecat.cmd == 5 && ecat.cnt == 0",
                                        {"ecat_mailbox.coe.sdoidx", "ecat_mailbox.coe.sdosub"});
    const auto answers = tshark_fields(dir / "sdo.pcap", "ecat_mailbox.coe && ecat.cmd == 4 && ecat.cnt == 1",
                                       {"ecat_mailbox.coe.type", "ecat_mailbox.coe.abortcode"});
    ASSERT_EQ(requests.size(), asked.size());
    ASSERT_EQ(answers.size(), asked.size());
    std::vector<std::string> theirs;
    std::size_t aborts = 0;
    for (std::size_t i = 0; i < requests.size(); ++i) {
        std::istringstream request(requests[i]), answer(answers[i]);
        std::string index, sub, service, code;
        std::getline(request, index, '\t');
        std::getline(request, sub, '\t');
        std::getline(answer, service, '\t');
        std::getline(answer, code, '\t');
        if (!code.empty()) {
            ++aborts;
            EXPECT_EQ(std::stoul(service), 2u) << "an abort is an SDO request (ETG.1000.6 5.6.2.7)";
            code = std::to_string(std::stoul(code, nullptr, 0));
        }
        theirs.push_back(std::to_string(std::stoul(index, nullptr, 0)) + "\t" + std::to_string(std::stoul(sub, nullptr, 0)) + "\t" + code);
    }
    EXPECT_EQ(theirs, ours);
    EXPECT_EQ(aborts, 3u);
}

}  // namespace
}  // namespace esi::test
