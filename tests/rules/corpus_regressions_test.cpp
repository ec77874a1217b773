// Real vendor files that once drew false alarms from pdo-/od- rules, and real defects the rules
// must keep finding. Skipped (with a message) when ../shared/corpus is absent.

#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "rules/pdo_od_test_support.hpp"

namespace {

using esi::test::findings_of;

esi::FileReport lint_corpus_file(const std::string& name) {
    esi::LintOptions options;
    options.jobs = 1;
    const auto path = esi::test::corpus_esi_dir() / name;
    EXPECT_TRUE(std::filesystem::exists(path)) << path;
    esi::LintReport report = esi::lint_paths({path}, options);
    if (report.files.empty()) return {};
    return std::move(report.files.front());
}

std::size_t count_containing(const esi::FileReport& report, std::string_view rule, std::string_view text) {
    std::size_t n = 0;
    for (const auto& d : findings_of(report, rule))
        if (d.message.find(text) != std::string::npos) ++n;
    return n;
}

TEST(CorpusRegressions, DevicesWithoutCoeNumberPdosFreely) {
    ESI_REQUIRE_CORPUS();
    // SoE drives (MDT/AT at IDN-based indices) and EL2262 oversampling PDOs at #x1800 without CoE.
    EXPECT_TRUE(findings_of(lint_corpus_file("Beckhoff__AX5xxx__dls-ethercat.xml"), "pdo-index-range").empty());
    EXPECT_TRUE(findings_of(lint_corpus_file("Beckhoff__EL2xxx__dls-ethercat.xml"), "pdo-index-range").empty());
}

TEST(CorpusRegressions, OneBufferOutputSmWithoutTypeTextIsAnOutputSm) {
    ESI_REQUIRE_CORPUS();
    EXPECT_TRUE(findings_of(lint_corpus_file("SMC__EX250-SEN1-X156__dls-ethercat__2011-05.xml"), "pdo-sm-direction").empty());
}

TEST(CorpusRegressions, BeckhoffProfileObjectsAndConventions) {
    ESI_REQUIRE_CORPUS();
    const auto el66 = lint_corpus_file("Beckhoff__EL66xx__dls-ethercat.xml");
    EXPECT_EQ(count_containing(el66, "pdo-entry-object-missing", "#x10F4"), 0u);
    EXPECT_EQ(count_containing(el66, "pdo-entry-object-missing", "#x18"), 0u);
    EXPECT_EQ(count_containing(el66, "pdo-entry-object-missing", "#xF"), 0u);
    EXPECT_EQ(count_containing(el66, "od-default-length", "is 0 bytes"), 0u) << "<DefaultData/> gives no value";
    const auto el3 = lint_corpus_file("Beckhoff__EL3xxx__dls-ethercat.xml");
    EXPECT_TRUE(findings_of(el3, "pdo-entry-not-mappable").empty()) << "0x1C33:20 has no PdoMapping flag at all";
    EXPECT_TRUE(findings_of(el3, "od-array-size").empty()) << "DT1C12ARR with Elements 0 is an empty list";
    EXPECT_TRUE(findings_of(lint_corpus_file("Beckhoff__EL15xx__dls-ethercat.xml"), "od-default-range").empty())
        << "MaxValue -1 of a UDINT is 0xFFFFFFFF";
    const auto el2 = lint_corpus_file("Beckhoff__EL2xxx__dls-ethercat.xml");
    EXPECT_EQ(count_containing(el2, "pdo-mapping-default", "entries, but"), 0u) << "trailing padding only in 0x1600";
}

TEST(CorpusRegressions, SoeDictionariesDefineTheirOwnTypesAndUnions) {
    ESI_REQUIRE_CORPUS();
    const auto ax = lint_corpus_file("Beckhoff__AX5101-xxxx-0210_Dict__dls-ethercat.xml");
    EXPECT_EQ(count_containing(ax, "od-subitem-layout", "overlaps"), 0u);
    EXPECT_TRUE(findings_of(ax, "od-nonstandard-type-name").empty()) << "INT8 and BIT are DataTypes the file defines";
    EXPECT_TRUE(findings_of(ax, "od-default-range").empty()) << "MinValue = MaxValue = 0 means no limits";
}

TEST(CorpusRegressions, RealDefectsAreStillFound) {
    ESI_REQUIRE_CORPUS();
    // C-style DataType names (pollen-robotics/pyesi output): a spelling warning naming the standard type.
    EXPECT_FALSE(findings_of(lint_corpus_file("PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml"), "pdo-entry-type-spelling").empty());
    // PDO entries that map the mapping object 0x1600 itself instead of 0x6040 …
    EXPECT_GT(count_containing(lint_corpus_file("Synapticon__Somanet_CiA402-multi__siitool__2022.xml"), "pdo-entry-object-missing",
                               "maps object #x1600"),
              0u);
    // An output object flagged 't' mapped into an RxPdo.
    EXPECT_FALSE(findings_of(lint_corpus_file("CSUFT__RT2000__wgy4188-EtherCAT-Slave.xml"), "pdo-entry-not-mappable").empty());
    // CX2040: the mailbox SMs overlap (MBoxOut #x1000 and MBoxIn #x1200, both 1024 bytes).
    EXPECT_GT(count_containing(lint_corpus_file("Beckhoff__CXxxxx__dls-ethercat.xml"), "sm-overlap", "MBoxIn"), 0u);
    // FB1111/FB1311 MCI DC: RxPdo 0x1A00 / TxPdo 0x1600 on a device that assigns and configures PDOs.
    EXPECT_GT(findings_of(lint_corpus_file("Beckhoff__FB1XXX__dls-ethercat.xml"), "pdo-index-range").size(), 0u);
    // A signed object described as UDINT in a PDO (S17).
    EXPECT_GT(count_containing(lint_corpus_file("Elmo__ECAT_00010420_V11__hw_device_mgr.xml"), "pdo-entry-object-type", "#x60FD"), 0u);
}

TEST(CorpusRegressions, NoRuleReportsTheSameFaultTwice) {
    ESI_REQUIRE_CORPUS();
    esi::LintOptions options;
    options.jobs = 2;
    const esi::LintReport report = esi::lint_paths({esi::test::corpus_esi_dir()}, options);
    ASSERT_FALSE(report.files.empty());
    for (const auto& file : report.files) {
        std::map<std::tuple<std::uint32_t, std::uint32_t, std::string, std::string>, int> seen;
        for (const auto& d : file.diagnostics) {
            if (d.rule.rfind("pdo-", 0) != 0 && d.rule.rfind("od-", 0) != 0) continue;
            const auto key = std::make_tuple(d.pos.line, d.pos.column, d.rule, d.message);
            EXPECT_EQ(++seen[key], 1) << file.path << ":" << d.pos.line << ": " << d.rule << ": " << d.message;
        }
    }
}

}  // namespace
