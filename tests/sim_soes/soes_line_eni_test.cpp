// esi-net's ENI applied by SOEM 2.x to the sample line (issue 21): samples/networks/line.yaml →
// esi-net build → SOEM's eniconv.py → a SOEM master built with that start-up table
// (ecx_contextt.ENI) brings the simulated line to OP. The digital I/O, the servo and the encoder
// run their SOES firmware (esi-gen's SOES set), the modular coupler with its three modules
// esi-sim's model slave (the SOES set holds no modules). What eniconv leaves out the master adds as a SOEM user must
// (docs/esi-net.md, "SOEM 2.x"): distributed clocks for the servo, and overlapped mapping, which
// places every variable at the offset process_image.json states.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "sim_soes/soes_fixtures.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

namespace fs = std::filesystem;

fs::path eniconv() { return shared_dir() / "tools" / "eni-readers" / "soem_eniconv.py"; }

// A copy of a device source whose ConfigData enables an SPI PDI, as the firmware needs: the
// first ten bytes of esi-gen's image with PDI control 0x05 (the network mode of the host builds
// each slave's image from its source, so the PDI must be in the source).
void enable_pdi(const fs::path& source, const fs::path& eeprom) {
    std::ifstream in(eeprom, std::ios::binary);
    std::vector<std::uint8_t> image((std::istreambuf_iterator<char>(in)), {});
    ASSERT_GE(image.size(), 16u);
    if (image[0] != 0) return;
    image[0] = 0x05;
    std::string config;
    for (int i = 0; i < 10; ++i) config += fmt::format("{:02X}", image[i]);
    std::istringstream text(read_text(source));
    std::string out, line;
    bool inserted = false;
    while (std::getline(text, line)) {
        out += line + "\n";
        if (!inserted && line.rfind("    revision:", 0) == 0) {
            out += "    eeprom: { config_data: " + config + " }\n";
            inserted = true;
        }
    }
    ASSERT_TRUE(inserted) << source;
    write_text(source, out);
}

void run_line() {
    TempDir dir;
    // A copy of the samples, whose firmware devices get a PDI (below).
    fs::copy(source_dir() / "samples", dir / "samples", fs::copy_options::recursive);
    const fs::path network = dir / "samples/networks/line.yaml";

    // esi-net's files for the line, and the C eniconv writes from its ENI.
    const fs::path net = dir / "net";
    const RunResult built = run({tool("esi-net").string(), "build", network.string(), "-o", net.string()});
    ASSERT_EQ(built.exit_code, 0) << built.err;
    const nlohmann::json image = nlohmann::json::parse(read_text(net / "process_image.json"));
    const RunResult converted = run({"python3", eniconv().string(), (net / "network.xml").string(), (dir / "eni.c").string()});
    ASSERT_EQ(converted.exit_code, 0) << converted.err;
    const std::string eni = read_text(dir / "eni.c");
    // What eniconv carries: CoE start-up commands, for the slaves that have them.
    EXPECT_NE(eni.find("ec_enit ec_eni"), std::string::npos) << eni;
    EXPECT_NE(eni.find(".Index = 0x6060"), std::string::npos) << "the servo's mode of operation";
    EXPECT_EQ(eni.find("Dc"), std::string::npos) << "eniconv now carries DC: update docs/esi-net.md";

    // SOEM 2.x's ecx_mbxENIinitcmds takes Ccs 2 for a download and 1 for an upload, the reverse
    // of ETG.2100 and of TwinCAT's and EC-Engineer's ENIs (Ccs 1: SDO initiate download), which
    // esi-net follows; eniconv copies Ccs and turns Timeout 0 (the tools' "default") into a 0 us
    // mailbox timeout. So a SOEM user fixes both in the converted table (docs/esi-net.md).
    std::string fixed = eni;
    for (const auto& [from, to] : {std::pair<std::string, std::string>{".Ccs = 1,", ".Ccs = 2,"},
                                   std::pair<std::string, std::string>{".Timeout = 0,", ".Timeout = EC_TIMEOUTRXM,"}}) {
        for (std::size_t at = fixed.find(from); at != std::string::npos; at = fixed.find(from, at + to.size()))
            fixed.replace(at, from.size(), to);
    }
    write_text(dir / "eni-fixed.c", fixed);

    // Two masters: with eniconv's table as written, and with the fixed one.
    const fs::path soem_build = ESI_SOEM_BUILD_DIR, soem = ESI_SOEM_SOURCE_DIR;
    const auto build_master = [&](const std::string& table) {
        const fs::path exe = dir / (table + "-master");
        const RunResult cc = run({"cc", "-O1", "-DESI_ENI_TABLE=ec_eni", "-I" + (soem_build / "include").string(),
                                  "-I" + (soem / "include").string(), "-I" + (soem / "osal").string(),
                                  "-I" + (soem / "osal/linux").string(), "-I" + (soem / "oshw/linux").string(),
                                  (source_dir() / "tests/sim_soes/soem/soes_master.c").string(), (dir / (table + ".c")).string(),
                                  (soem_build / "libsoem.a").string(), "-lpthread", "-lrt", "-o", exe.string()});
        EXPECT_EQ(cc.exit_code, 0) << cc.err;
        return exe;
    };
    const fs::path as_converted = build_master("eni"), master = build_master("eni-fixed");

    // The simulated line: the copy, whose firmware devices have a PDI.
    std::vector<std::string> host{network.string()};
    std::map<std::string, int> soes_position;  // Type text -> bus position
    for (const auto& [file, position] : {std::pair{"digital-io-8", 1}, std::pair{"servo-item-c-series", 2},
                                         std::pair{"encoder-tr-linear", 3}}) {
        const SoesFirmware& fw = soes_firmware(source_dir() / "samples" / (std::string(file) + ".yaml"));
        ASSERT_EQ(fw.error, "") << file;
        enable_pdi(dir / "samples" / (std::string(file) + ".yaml"), fw.generated / "eeprom.bin");
        host.insert(host.end(), {"--firmware", fw.selector + "=" + fw.library.string()});
        soes_position[fw.type] = position;
    }
    // The coupler runs the model slave, which needs a PDI as well.
    ASSERT_EQ(run({tool("esi-gen").string(), (source_dir() / "samples/modular-coupler.yaml").string(), "-o",
                   (dir / "coupler").string(), "--only", "sii"})
                  .exit_code,
              0);
    enable_pdi(dir / "samples/modular-coupler.yaml", dir / "coupler" / "eeprom.bin");
    // DC: the servo (position 2, SOEM slave 3) runs SYNC0 at the network's cycle.
    const std::vector<std::string> args{"--cycles", "1000", "--state-timeout-ms", "3000", "--overlap", "--dc-sync0", "3:1000000"};
    const auto results = run_soes_session({{host, args, as_converted.string(), false}, {host, args, master.string(), false}});
    ASSERT_EQ(results.size(), 2u);

    // As converted, SOEM uploads where the ENI downloads: the servo keeps its default
    // assignment of four PDOs instead of the network's two.
    ASSERT_TRUE(results[0].master) << results[0].host_stderr << results[0].master_output;
    EXPECT_EQ((*results[0].master)["slave"][2]["assign"]["7186"].size(), 4u);

    const SoesStepResult& r = results[1];
    ASSERT_TRUE(r.master) << r.host_stderr << r.master_output;
    ASSERT_TRUE(r.host) << r.host_stderr << r.host_output;
    const auto& m = *r.master;
    ASSERT_EQ(m["slaves"], 4);
    ASSERT_EQ(m["op"], true) << m.dump() << r.host_stderr;
    EXPECT_EQ(m["wkc_ok"], 1000) << "expected working counter " << m["expected_wkc"];

    // Overlapped mapping: each slave at the byte offset process_image.json gives, for both
    // directions, and the images as large as its slaves' span.
    for (const auto& slave : image["slaves"]) {
        const auto& s = m["slave"][slave["position"].get<int>()];
        SCOPED_TRACE(slave["name"].get<std::string>());
        EXPECT_EQ(s["state"], 8);
        if (slave["output_bytes"] > 0) {
            EXPECT_EQ(s["output_offset"], slave["byte_offset"]);
        }
        if (slave["input_bytes"] > 0) {
            EXPECT_EQ(s["input_offset"], slave["byte_offset"]);
        }
    }
    // The ENI's PDO assignment commands were applied: the servo has the four PDOs the network
    // chose, the coupler its modules' PDOs.
    const auto pdos = [](const nlohmann::json& list) {
        std::vector<unsigned> out;
        for (const auto& p : list) out.push_back(p["pdo"].get<unsigned>());
        return out;
    };
    EXPECT_EQ(pdos(m["slave"][2]["assign"]["7186"]), (std::vector<unsigned>{0x1600, 0x1601}));
    EXPECT_EQ(pdos(m["slave"][2]["assign"]["7187"]), (std::vector<unsigned>{0x1A00, 0x1A01}));
    EXPECT_EQ(pdos(m["slave"][0]["assign"]["7186"]), (std::vector<unsigned>{0x1601}));
    EXPECT_EQ(pdos(m["slave"][0]["assign"]["7187"]), (std::vector<unsigned>{0x1A00, 0x1A02}));

    // The SOES slaves' variables, bit for bit at process_image.json's offsets.
    ASSERT_EQ(r.host->size(), soes_position.size());
    for (const auto& h : *r.host) {
        SCOPED_TRACE(h["name"].get<std::string>());
        ASSERT_TRUE(soes_position.count(h["name"]));
        expect_variables_match(image, soes_position[h["name"]], m, h);
    }
}

#define ESI_REQUIRE_ENICONV()                                                                                      \
    do {                                                                                                           \
        ESI_REQUIRE_SOES_ON_SIM();                                                                                 \
        if (!fs::exists(eniconv())) GTEST_SKIP() << "no SOEM eniconv.py at " << eniconv();                        \
        if (run({"sh", "-c", "command -v python3"}).exit_code != 0) GTEST_SKIP() << "no python3 for eniconv.py"; \
    } while (0)

TEST(SoesLineEni, SoemAppliesEsiNetsEniAndPlacesEveryVariableWhereProcessImageJsonSays) {
    ESI_REQUIRE_ENICONV();
    run_line();
}

}  // namespace
}  // namespace esi::test
