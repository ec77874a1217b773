// SOEM 2.x runs samples/networks/line.yaml through esi-sim, configured with the start-up commands
// `esi-net build` wrote for the same file, and sees what esi-net wrote: identities, positions and
// process-data sizes.

#include <gtest/gtest.h>

#include <pugixml.hpp>

#include "sim_esc/sim_fixtures.hpp"
#include "sim_esc/soem_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

std::uint32_t hex_number(const nlohmann::json& value) { return static_cast<std::uint32_t>(std::stoul(value.get<std::string>(), nullptr, 16)); }

// The ENI's CoE start-up commands for PREOP->SAFEOP, as soem_master --init arguments.
std::vector<std::string> ps_init_commands(const std::filesystem::path& eni) {
    std::vector<std::string> args;
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file(eni.c_str()));
    int position = 0;
    for (const pugi::xml_node slave : doc.child("EtherCATConfig").child("Config").children("Slave")) {
        for (const pugi::xml_node cmd : slave.child("Mailbox").child("CoE").child("InitCmds").children("InitCmd")) {
            if (std::string(cmd.child_value("Transition")) != "PS") continue;
            args.push_back("--init");
            args.push_back(std::to_string(position) + ":" + cmd.child_value("Index") + ":" + cmd.child_value("SubIndex") + ":" +
                           (cmd.attribute("CompleteAccess").as_bool() ? "1" : "0") + ":" + cmd.child_value("Data"));
        }
        ++position;
    }
    return args;
}

TEST(SoemLine, TheSampleLineMatchesWhatEsiNetWroteAndRunsInOp) {
    ESI_REQUIRE_SOEM();
    const auto network = source_dir() / "samples" / "networks" / "line.yaml";
    TempDir dir;
    const RunResult built = run({tool("esi-net").string(), "build", network.string(), "-o", (dir / "net").string()});
    ASSERT_EQ(built.exit_code, 0) << built.err;
    const auto image = nlohmann::json::parse(read_text(dir / "net" / "process_image.json"));
    const auto& expected = image["slaves"];
    std::vector<std::string> master_args = {"--cycles", "1000", "--state-timeout-ms", "3000"};
    for (const std::string& a : ps_init_commands(dir / "net" / "network.xml")) master_args.push_back(a);

    const auto results = run_soem_session({{{network.string()}, master_args}});
    ASSERT_TRUE(results[0].report) << results[0].sim_stderr << results[0].master_output;
    const auto& r = *results[0].report;
    EXPECT_NE(results[0].sim_stderr.find("esi-sim: 4 slave(s) on v1"), std::string::npos) << results[0].sim_stderr;
    ASSERT_EQ(r["slaves"], expected.size());

    for (std::size_t i = 0; i < expected.size(); ++i) {
        const auto& want = expected[i];
        const auto& got = r["slave"][i];
        SCOPED_TRACE(want["name"].get<std::string>());
        EXPECT_EQ(got["position"], want["position"]);
        EXPECT_EQ(got["vendor"], hex_number(want["vendor_id"]));
        EXPECT_EQ(got["product"], hex_number(want["product_code"]));
        EXPECT_EQ(got["revision"], hex_number(want["revision"]));
        EXPECT_EQ(got["name"], want["type"]);
    }
    // Every sample names its ESC (an `esc:` preset), so every firmware has its PDI and the whole
    // line reaches OP.
    EXPECT_EQ(r["init_cmd_failures"], 0);
    EXPECT_EQ(r["op"], true);
    EXPECT_EQ(r["wkc_ok"], 1000) << "expected working counter " << r["expected_wkc"];
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const auto& got = r["slave"][i];
        SCOPED_TRACE(expected[i]["name"].get<std::string>());
        EXPECT_EQ((got["obits"].get<unsigned>() + 7) / 8, expected[i]["output_bytes"].get<unsigned>());
        EXPECT_EQ((got["ibits"].get<unsigned>() + 7) / 8, expected[i]["input_bytes"].get<unsigned>());
    }
}

}  // namespace
}  // namespace esi::test
