// lcec.xml against linuxcnc-ethercat configurations in ../shared/corpus/master-configs/lcec/:
//  - RTIC-ECMaster's config, written from the Bohign/YAKO ESI that is in the corpus: the same
//    SyncManagers, PDOs, entries (index, sub-index, bit length, HAL type), DC and start-up SDO;
//    its pin names are hand-made ("drive0-actual-position") where esi-net derives them from the
//    ESI's entry names as lcec_configgen does;
//  - lcec_configgen's golden file of a real 20-slave bus: `esi-net init --from-igh` on the
//    scan it was made from names the same 20 devices; none of them has an ESI in the corpus, so
//    `build` must stop with the nearest identities (and write nothing); the HAL types of the CiA
//    402 objects the golden maps are compared on a corpus drive that maps the same objects.

#include <gtest/gtest.h>

#include <pugixml.hpp>

#include <map>

#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

fs::path lcec_dir() { return esi::test::corpus_dir() / "master-configs" / "lcec"; }

unsigned long number(const std::string& text, int base = 16) {
    std::string t = text;
    if (t.rfind("0x", 0) == 0 || t.rfind("0X", 0) == 0) t = t.substr(2);
    return std::stoul(t, nullptr, base);
}

// One slave's lcec content without its pin names: SMs with PDOs, entries with their HAL type,
// dcConf and sdoConfig, numbers normalised (hex with or without 0x, any case).
std::vector<std::string> slave_facts(const pugi::xml_node& slave) {
    std::vector<std::string> out;
    for (pugi::xml_node dc : slave.children("dcConf"))
        out.push_back("dc " + std::to_string(number(dc.attribute("assignActivate").as_string())) + " " + dc.attribute("sync0Cycle").as_string() +
                      " " + dc.attribute("sync0Shift").as_string());
    for (pugi::xml_node sdo : slave.children("sdoConfig")) {
        std::string data;
        for (pugi::xml_node raw : sdo.children("sdoDataRaw")) data += raw.attribute("data").as_string();
        const std::string sub = sdo.attribute("subIdx").as_string();
        out.push_back("sdo " + std::to_string(number(sdo.attribute("idx").as_string())) + ":" +
                      (sub == "complete" ? sub : std::to_string(number(sub))) + " " + data);
    }
    for (pugi::xml_node sm : slave.children("syncManager")) {
        if (!sm.child("pdo")) continue;
        out.push_back(std::string("sm ") + sm.attribute("idx").as_string() + " " + sm.attribute("dir").as_string());
        for (pugi::xml_node pdo : sm.children("pdo")) {
            out.push_back("pdo " + std::to_string(number(pdo.attribute("idx").as_string())));
            for (pugi::xml_node e : pdo.children("pdoEntry"))
                out.push_back("entry " + std::to_string(number(e.attribute("idx").as_string())) + ":" +
                              std::to_string(number(e.attribute("subIdx").as_string())) + " " + e.attribute("bitLen").as_string() + " " +
                              e.attribute("halType").as_string());
        }
    }
    return out;
}

TEST(Lcec, MatchesTheConfigWrittenFromTheSameEsi) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(R"(master: { name: bohign, cycle_time_us: 10000, lcec_fork: sittner }
slaves:
  - { name: drive0, vendor_id: 0x994, product_code: 0x1B00 }
  - { name: drive1, vendor_id: 0x994, product_code: 0x1B00 }
)");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    const std::string ours_text = esi::net::write_lcec(*built.network);
    pugi::xml_document ours, theirs;
    ASSERT_TRUE(ours.load_string(ours_text.c_str()));
    ASSERT_TRUE(theirs.load_file((lcec_dir() / "RTIC-ECMaster__ethercat-conf.bohign.xml").c_str()));
    const pugi::xml_node a = ours.child("masters").child("master");
    const pugi::xml_node b = theirs.child("masters").child("master");
    EXPECT_STREQ(a.attribute("appTimePeriod").as_string(), b.attribute("appTimePeriod").as_string());
    EXPECT_STREQ(a.attribute("refClockSlaveIdx").as_string(), b.attribute("refClockSlaveIdx").as_string());
    std::vector<pugi::xml_node> ours_slaves, their_slaves;
    for (pugi::xml_node s : a.children("slave")) ours_slaves.push_back(s);
    for (pugi::xml_node s : b.children("slave")) their_slaves.push_back(s);
    ASSERT_EQ(ours_slaves.size(), their_slaves.size());
    for (std::size_t i = 0; i < ours_slaves.size(); ++i) {
        EXPECT_EQ(number(ours_slaves[i].attribute("vid").as_string()), number(their_slaves[i].attribute("vid").as_string()));
        EXPECT_EQ(number(ours_slaves[i].attribute("pid").as_string()), number(their_slaves[i].attribute("pid").as_string()));
        EXPECT_EQ(slave_facts(ours_slaves[i]), slave_facts(their_slaves[i])) << "slave " << i;
    }
}

TEST(Lcec, HalTypesOfCia402ObjectsAgreeWithLcecConfiggen) {
    ESI_REQUIRE_CORPUS();
    // The Elmo drive maps the CiA 402 objects of the golden's L7EC drives (those its ESI lets an
    // RxPDO or TxPDO carry) into its configurable PDOs.
    const esi::net::BuildResult built = esi::test::build_corpus_network(R"(master: { name: cia }
slaves:
  - name: D1
    product_code: 0x00030924
    revision: 0x00010420
    pdos: [0x1607, 0x1A07, 0x1A08]
    pdo_entries:
      0x1607: [0x6040:0:16, 0x6060:0:8, 0x607A:0:32, 0x60FF:0:32]
      0x1A07: [0x6041:0:16, 0x606C:0:32, 0x6064:0:32, 0x603F:0:16]
      0x1A08: [0x6077:0:16, 0x60F4:0:32, 0x60FD:0:32]
)");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    auto types = [](const pugi::xml_node& slave) {
        std::map<std::string, std::string> out;
        for (const pugi::xpath_node& n : slave.select_nodes(".//pdoEntry"))
            out[std::to_string(number(n.node().attribute("idx").as_string())) + ":" + n.node().attribute("subIdx").as_string() + ":" +
                n.node().attribute("bitLen").as_string()] = n.node().attribute("halType").as_string();
        return out;
    };
    pugi::xml_document ours, golden;
    const std::string text = esi::net::write_lcec(*built.network);
    ASSERT_TRUE(ours.load_string(text.c_str()));
    ASSERT_TRUE(golden.load_file((lcec_dir() / "lcec__configgen__golden_realbus.xml").c_str()));
    const auto ours_types = types(ours.child("masters").child("master").child("slave"));
    const auto golden_types = types(golden.child("masters").child("master").child("slave"));  // D1, an L7EC drive
    std::size_t compared = 0;
    for (const auto& [key, type] : ours_types) {
        const auto it = golden_types.find(key);
        if (it == golden_types.end()) continue;
        EXPECT_EQ(type, it->second) << key;
        ++compared;
    }
    EXPECT_EQ(compared, 11u);
}

TEST(Lcec, InitFromTheRealBusScanNamesTheGoldenDevices) {
    ESI_REQUIRE_CORPUS();
    esi::test::TempDir dir;
    const auto init = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "init", "--from-igh",
                                      (lcec_dir() / "lcec__configgen__canned_realbus_slaves.txt").string(), "-o", (dir / "bus.yaml").string()});
    ASSERT_EQ(init.exit_code, 0) << init.err;
    const esi::net::NetworkFileResult read = esi::net::read_network_file((dir / "bus.yaml").string());
    ASSERT_TRUE(read.spec) << esi::test::diagnostics_text(read.diagnostics);
    pugi::xml_document golden;
    ASSERT_TRUE(golden.load_file((lcec_dir() / "lcec__configgen__golden_realbus.xml").c_str()));
    std::vector<std::pair<unsigned long, unsigned long>> golden_ids;
    std::vector<std::string> golden_names;
    for (pugi::xml_node s : golden.child("masters").child("master").children("slave")) {
        golden_ids.emplace_back(number(s.attribute("vid").as_string()), number(s.attribute("pid").as_string()));
        golden_names.push_back(s.attribute("name").as_string());
    }
    ASSERT_EQ(read.spec->slaves.size(), golden_ids.size());
    for (std::size_t i = 0; i < golden_ids.size(); ++i) {
        const esi::net::SlaveSpec& s = read.spec->slaves[i];
        EXPECT_EQ(s.name, golden_names[i]);
        EXPECT_EQ(s.vendor_id, golden_ids[i].first);
        EXPECT_EQ(s.product_code, golden_ids[i].second);
        EXPECT_TRUE(s.revision.has_value());
    }

    // No ESI of these devices is in the corpus: the build names each and writes nothing.
    const auto build = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "build", (dir / "bus.yaml").string(), "-o",
                                       (dir / "out").string(), "--only", "lcec", "--esi", esi::test::corpus_esi_dir().string()});
    EXPECT_EQ(build.exit_code, 1) << build.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "lcec.xml"));
    std::size_t unknown = 0;
    for (std::size_t at = 0; (at = build.err.find("[net-device-unknown]", at)) != std::string::npos; ++at) ++unknown;
    EXPECT_EQ(unknown, golden_ids.size()) << build.err;
    EXPECT_NE(build.err.find("no ESI file describes vendor 0x00004321, product code 0x000000B4, revision 0x00000001"), std::string::npos)
        << build.err;
    EXPECT_NE(build.err.find("looked in"), std::string::npos);
}

}  // namespace
