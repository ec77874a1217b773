// lcec.xml and the two maintained linuxcnc-ethercat forks (rules in lcec_fork_rules.hpp):
//  - the checker itself on the corpus configurations: each fork's files pass its own rules,
//    and what one fork refuses of the other's is exactly the difference (refClockSlaveIdx);
//    lcec_configgen's realbus golden writes `halType="BLANK"` for types it cannot infer,
//    which the linuxcnc-ethercat reader refuses: those 17 entries and nothing else;
//  - esi-net's lcec.xml of every corpus network under each fork's rules, written for that fork;
//  - refClockSlaveIdx only for sittner, 64-bit entries mapped without a pin.

#include <gtest/gtest.h>

#include <algorithm>

#include "esi/net/outputs.hpp"
#include "net/lcec_fork_rules.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::test::LcecForkRules;

fs::path lcec_dir() { return esi::test::corpus_dir() / "master-configs" / "lcec"; }

std::vector<esi::test::LcecRefusal> refusals_of_file(const std::string& name, LcecForkRules fork) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file((lcec_dir() / name).c_str())) << name;
    return esi::test::lcec_refusals(doc, fork);
}

std::string joined(const std::vector<esi::test::LcecRefusal>& refusals) {
    std::string out;
    for (const auto& r : refusals) out += r.message + "\n";
    return out;
}

// The linuxcnc-ethercat fork's own examples and configgen golden (PROVENANCE.tsv).
constexpr const char* linuxcnc_ethercat_files[] = {"lcec__CPD17__ethercat-conf_X.xml", "lcec__generic-complex__ethercat-conf.xml",
                                                   "lcec__initcmds__ethercat-conf.xml", "lcec__configgen__golden_scenario1.xml"};

TEST(LcecForks, TheLinuxcncEthercatForksFilesPassItsRules) {
    ESI_REQUIRE_CORPUS();
    for (const char* f : linuxcnc_ethercat_files)
        EXPECT_EQ(joined(refusals_of_file(f, LcecForkRules::linuxcnc_ethercat)), "") << f;
}

TEST(LcecForks, ConfiggensRealbusGoldenIsRefusedOnlyForItsBlankHalTypes) {
    ESI_REQUIRE_CORPUS();
    const auto refusals = refusals_of_file("lcec__configgen__golden_realbus.xml", LcecForkRules::linuxcnc_ethercat);
    ASSERT_EQ(refusals.size(), 17u) << joined(refusals);
    for (const auto& r : refusals) EXPECT_NE(r.message.find("halType BLANK"), std::string::npos) << r.message;
}

TEST(LcecForks, RticsConfigUsesSittnersRefClockSlaveIdx) {
    ESI_REQUIRE_CORPUS();
    // Written for the sittner fork's reader: accepted there, and the linuxcnc-ethercat reader
    // refuses exactly its refClockSlaveIdx.
    const char* file = "RTIC-ECMaster__ethercat-conf.bohign.xml";
    EXPECT_EQ(joined(refusals_of_file(file, LcecForkRules::sittner)), "");
    const auto refusals = refusals_of_file(file, LcecForkRules::linuxcnc_ethercat);
    ASSERT_EQ(refusals.size(), 1u) << joined(refusals);
    EXPECT_NE(refusals[0].message.find("refClockSlaveIdx"), std::string::npos);
}

TEST(LcecForks, SittnersRulesRefuseWhatOnlyTheOtherForkReads) {
    // The checker can fail: each fork's additions are refused by the other's rules.
    const std::string double_ieee = R"(<masters><master idx="0" syncToRefClock="true"><slave idx="0" type="generic" vid="2" pid="3">
<syncManager idx="3" dir="in"><pdo idx="1a00"><pdoEntry idx="6000" subIdx="01" bitLen="64" halType="float-double-ieee" halPin="x"/></pdo></syncManager>
</slave></master></masters>)";
    const auto sittner = esi::test::lcec_refusals(double_ieee, LcecForkRules::sittner);
    ASSERT_EQ(sittner.size(), 2u) << joined(sittner);
    EXPECT_NE(joined(sittner).find("syncToRefClock"), std::string::npos);
    EXPECT_NE(joined(sittner).find("float-double-ieee"), std::string::npos);
    EXPECT_EQ(joined(esi::test::lcec_refusals(double_ieee, LcecForkRules::linuxcnc_ethercat)), "");
    const std::string u64 = R"(<masters><master idx="0"><slave idx="0" type="EK1100" vid="2"><syncManager idx="0" dir="out"/></slave></master></masters>)";
    EXPECT_EQ(esi::test::lcec_refusals(u64, LcecForkRules::sittner).size(), 2u);  // vid and syncManager on a non-generic slave
    EXPECT_EQ(esi::test::lcec_refusals(u64, LcecForkRules::linuxcnc_ethercat).size(), 1u);  // syncManager only
}

class LcecForOneFork : public ::testing::TestWithParam<LcecForkRules> {};

TEST_P(LcecForOneFork, EveryCorpusNetworkIsReadByThatFork) {
    ESI_REQUIRE_CORPUS();
    const LcecForkRules rules = GetParam();
    int checked = 0;
    for (const esi::test::NamedNetwork& n : esi::test::corpus_networks()) {
        const esi::net::BuildResult built = esi::test::build_corpus_network(n.yaml, n.name + ".yaml");
        ASSERT_TRUE(built.network) << n.name << "\n" << esi::test::diagnostics_text(built.diagnostics);
        esi::net::Network network = *built.network;
        network.master.lcec_fork = rules == LcecForkRules::sittner ? esi::net::LcecFork::sittner : esi::net::LcecFork::linuxcnc_ethercat;
        const std::string text = esi::net::write_lcec(network);
        EXPECT_EQ(joined(esi::test::lcec_refusals(text, rules)), "") << n.name << "\n" << text;
        ++checked;
    }
    EXPECT_GE(checked, 4);
}

INSTANTIATE_TEST_SUITE_P(Forks, LcecForOneFork, ::testing::Values(LcecForkRules::linuxcnc_ethercat, LcecForkRules::sittner),
                         [](const auto& info) { return info.param == LcecForkRules::sittner ? "sittner" : "linuxcnc_ethercat"; });

// An Elmo drive in DC mode: a reference clock, and 32-bit entries only.
const char* const dc_network = R"(master: { cycle_time_us: 1000 }
slaves:
  - { name: coupler, device: EK1100 }
  - { name: axis, product_code: 0x00030924, revision: 0x00010420 }
)";

TEST(LcecForks, RefClockSlaveIdxOnlyForSittner) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(dc_network);
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    ASSERT_TRUE(built.network->reference_clock.has_value());
    esi::net::Network network = *built.network;
    const std::string default_text = esi::net::write_lcec(network);
    EXPECT_EQ(default_text.find("refClockSlaveIdx="), std::string::npos) << default_text;
    EXPECT_NE(default_text.find("github.com/linuxcnc-ethercat/linuxcnc-ethercat"), std::string::npos);
    network.master.lcec_fork = esi::net::LcecFork::sittner;
    const std::string sittner_text = esi::net::write_lcec(network);
    EXPECT_NE(sittner_text.find("refClockSlaveIdx=\"" + std::to_string(*network.reference_clock) + "\""), std::string::npos);
    EXPECT_NE(sittner_text.find("github.com/sittner/linuxcnc-ethercat"), std::string::npos);
}

TEST(LcecForks, TheForkIsANetworkFileSetting) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult sittner = esi::test::build_corpus_network("master: { lcec_fork: sittner }\nslaves:\n  - { device: EK1100 }\n");
    ASSERT_TRUE(sittner.network) << esi::test::diagnostics_text(sittner.diagnostics);
    EXPECT_EQ(sittner.network->master.lcec_fork, esi::net::LcecFork::sittner);
    const esi::net::BuildResult wrong = esi::test::build_corpus_network("master: { lcec_fork: master }\nslaves:\n  - { device: EK1100 }\n");
    EXPECT_FALSE(wrong.network);
    EXPECT_NE(esi::test::diagnostics_text(wrong.diagnostics).find("'lcec_fork' must be 'linuxcnc-ethercat' or 'sittner'"), std::string::npos);
}

TEST(LcecForks, A64BitEntryIsMappedWithoutAPin) {
    ESI_REQUIRE_CORPUS();
    // EasyCAT's custom slave maps a LINT (0x0005:01, 64 bits): neither fork has a 64-bit HAL
    // type, so the entry keeps its place in the mapping, without halPin and halType.
    const esi::net::BuildResult built =
        esi::test::build_corpus_network("slaves:\n  - { name: easy, vendor_id: 0x79A, product_code: 0xDEADBEEF }\n");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    for (const esi::net::LcecFork fork : {esi::net::LcecFork::linuxcnc_ethercat, esi::net::LcecFork::sittner}) {
        esi::net::Network network = *built.network;
        network.master.lcec_fork = fork;
        const std::string text = esi::net::write_lcec(network);
        EXPECT_NE(text.find("<pdoEntry idx=\"0005\" subIdx=\"01\" bitLen=\"64\"/>"), std::string::npos) << text;
        EXPECT_NE(text.find("0x0005:01 (64 bits) has no HAL pin"), std::string::npos) << text;
        EXPECT_NE(text.find("halType=\"float-ieee\""), std::string::npos);  // the REAL beside it keeps its pin
        const LcecForkRules rules = fork == esi::net::LcecFork::sittner ? LcecForkRules::sittner : LcecForkRules::linuxcnc_ethercat;
        EXPECT_EQ(joined(esi::test::lcec_refusals(text, rules)), "") << text;
    }
}

}  // namespace
