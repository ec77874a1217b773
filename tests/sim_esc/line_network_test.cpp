// samples/networks/line.yaml through esi-sim's line, configured with the CoE start-up commands
// `esi-net build` wrote into the ENI for the same file: the master finds what esi-net wrote
// (identities, positions, types, process-data sizes) and the whole line runs in OP.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "sim_esc/line_master.hpp"
#include "sim_esc/line_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

std::uint32_t hex_number(const nlohmann::json& value) { return static_cast<std::uint32_t>(std::stoul(value.get<std::string>(), nullptr, 16)); }

struct InitCommand {
    std::size_t position = 0;
    std::uint16_t index = 0;
    std::uint8_t subindex = 0;
    bool complete_access = false;
    std::vector<std::uint8_t> data;
};

// The ENI's CoE start-up commands for PREOP->SAFEOP, in file order.
std::vector<InitCommand> ps_commands(const std::filesystem::path& eni) {
    std::vector<InitCommand> out;
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file(eni.c_str()));
    std::size_t position = 0;
    for (const pugi::xml_node slave : doc.child("EtherCATConfig").child("Config").children("Slave")) {
        for (const pugi::xml_node cmd : slave.child("Mailbox").child("CoE").child("InitCmds").children("InitCmd")) {
            bool ps = false;
            for (const pugi::xml_node t : cmd.children("Transition")) ps = ps || std::string(t.text().get()) == "PS";
            if (!ps) continue;
            InitCommand c;
            c.position = position;
            c.index = static_cast<std::uint16_t>(std::stoul(cmd.child_value("Index"), nullptr, 0));
            c.subindex = static_cast<std::uint8_t>(std::stoul(cmd.child_value("SubIndex"), nullptr, 0));
            c.complete_access = std::string(cmd.attribute("CompleteAccess").value()) == "1";
            const std::string hex = cmd.child_value("Data");
            for (std::size_t i = 0; i + 1 < hex.size(); i += 2) c.data.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
            out.push_back(std::move(c));
        }
        ++position;
    }
    return out;
}

TEST(LineNetwork, TheSampleLineMatchesWhatEsiNetWroteAndRunsInOp) {
    const auto network = source_dir() / "samples" / "networks" / "line.yaml";
    TempDir dir;
    const RunResult built = run({tool("esi-net").string(), "build", network.string(), "-o", (dir / "net").string()});
    ASSERT_EQ(built.exit_code, 0) << built.err;
    const auto image = nlohmann::json::parse(read_text(dir / "net" / "process_image.json"));
    const auto& expected = image["slaves"];
    const std::vector<InitCommand> commands = ps_commands(dir / "net" / "network.xml");
    ASSERT_FALSE(commands.empty());

    std::string error;
    std::optional<sim::Line> line = network_line(network, false, error);
    ASSERT_TRUE(line) << error;
    LineMaster master(*line);
    ASSERT_TRUE(master.scan());
    ASSERT_EQ(master.slaves.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const auto& want = expected[i];
        const sii::Image& got = master.slaves[i].decoded.image;
        SCOPED_TRACE(want["name"].get<std::string>());
        EXPECT_EQ(want["position"], i);
        EXPECT_EQ(got.header.vendor_id, hex_number(want["vendor_id"]));
        EXPECT_EQ(got.header.product_code, hex_number(want["product_code"]));
        EXPECT_EQ(got.header.revision_no, hex_number(want["revision"]));
        ASSERT_NE(got.general(), nullptr);
        EXPECT_EQ(got.string_at(got.general()->order_idx), want["type"].get<std::string>());
    }

    for (LineSlave& s : master.slaves) {
        ASSERT_TRUE(master.setup_mailbox(s));
        const StateResult r = master.request_state(s, 2);
        ASSERT_EQ(r.state(), 2) << "AL status code 0x" << std::hex << r.al_status_code;
    }
    for (const InitCommand& c : commands)
        EXPECT_EQ(master.download(master.slaves[c.position], c.index, c.subindex, c.data, c.complete_access), 0u)
            << "slave " << c.position << " 0x" << std::hex << c.index << ":" << unsigned(c.subindex);
    const std::uint16_t expected_wkc = master.setup_process_data();
    for (std::size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE(expected[i]["name"].get<std::string>());
        EXPECT_EQ(master.slaves[i].output_bytes(), expected[i]["output_bytes"].get<unsigned>());
        EXPECT_EQ(master.slaves[i].input_bytes(), expected[i]["input_bytes"].get<unsigned>());
    }
    for (LineSlave& s : master.slaves) {
        const StateResult r = master.request_state(s, 4);
        ASSERT_EQ(r.state(), 4) << "AL status code 0x" << std::hex << r.al_status_code;
    }
    for (LineSlave& s : master.slaves) {
        const StateResult r = master.request_state(s, 8);
        ASSERT_EQ(r.al_status, 8) << "AL status code 0x" << std::hex << r.al_status_code;
    }
    unsigned wkc_ok = 0;
    for (unsigned c = 0; c < 1000; ++c) {
        const auto a = master.cycle(std::vector<std::uint8_t>(master.output_image_bytes(), static_cast<std::uint8_t>(c)));
        if (a && a->working_counter == expected_wkc) ++wkc_ok;
    }
    EXPECT_EQ(wkc_ok, 1000u) << "expected working counter " << expected_wkc;
    for (const LineSlave& s : master.slaves) EXPECT_EQ(master.state_of(s).al_status, 8);
}

}  // namespace
}  // namespace esi::test
