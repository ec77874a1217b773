// Without `revision:`, the highest revision a current catalogue offers (issue 24 §4). Beckhoff's
// pre-ETG.2000 "EtherCAT Terminals" file numbers its devices 0x270B0000 (ProductRevision
// …-9995), above every current revision; the current catalogues list those revisions as a
// HideType of their revision-0 device. A revision some device hides is passed over, and the
// note says which revision and file were taken and why.

#include <gtest/gtest.h>

#include <cstdio>

#include "esi/net/library_index.hpp"
#include "esi/net/resolve.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::net::DeviceQuery;

std::string message_and_notes(const esi::Diagnostics& diagnostics) { return esi::test::diagnostics_text(diagnostics); }

struct Case {
    const char* type;
    std::uint32_t expected;
    std::uint32_t legacy;  // the higher legacy revision passed over
};

TEST(RevisionChoice, CorpusDevicesInLegacyAndCurrentFilesTakeTheCurrentRevision) {
    ESI_REQUIRE_CORPUS();
    const esi::net::LibraryIndex& index = esi::test::corpus_index();
    for (const Case& c : {Case{"EK1100", 0x00120000, 0x270B0000}, Case{"EL2002", 0x00120000, 0x270B0000},
                          Case{"EL4102", 0x03FA0000, 0x270B0000}, Case{"EL1002", 0x00100000, 0x270B0000}}) {
        SCOPED_TRACE(c.type);
        const esi::net::Resolution res = esi::net::resolve_device(index, DeviceQuery{c.type, std::nullopt, std::nullopt, std::nullopt}, "n.yaml", {4, 5});
        ASSERT_NE(res.device, nullptr) << message_and_notes(res.diagnostics);
        EXPECT_EQ(res.device->revision_no, c.expected);
        EXPECT_EQ(index.file_of(*res.device).path.find("EtherCAT_Terminals"), std::string::npos);
        const std::string text = message_and_notes(res.diagnostics);
        char taken[16], passed[16];
        std::snprintf(taken, sizeof taken, "0x%08X", c.expected);
        std::snprintf(passed, sizeof passed, "0x%08X", c.legacy);
        EXPECT_NE(text.find(std::string("n.yaml:4:5: info: no revision given: using ") + taken + " from "), std::string::npos) << text;
        EXPECT_NE(text.find("that no current catalogue hides"), std::string::npos) << text;
        EXPECT_NE(text.find(std::string("passed over: ") + passed + " is a legacy revision"), std::string::npos) << text;
        EXPECT_NE(text.find("Beckhoff__EtherCAT_Terminals__dls-ethercat.xml:"), std::string::npos) << text;
    }
}

TEST(RevisionChoice, AnExplicitLegacyRevisionIsStillTaken) {
    ESI_REQUIRE_CORPUS();
    const esi::net::LibraryIndex& index = esi::test::corpus_index();
    const esi::net::Resolution res =
        esi::net::resolve_device(index, DeviceQuery{"EK1100", std::nullopt, std::nullopt, 0x270B0000}, "n.yaml", {});
    ASSERT_NE(res.device, nullptr) << message_and_notes(res.diagnostics);
    EXPECT_NE(index.file_of(*res.device).path.find("EtherCAT_Terminals"), std::string::npos);
    EXPECT_TRUE(res.diagnostics.empty()) << message_and_notes(res.diagnostics);
}

TEST(RevisionChoice, ANetworkWithoutRevisionsBuildsTheCurrentCoupler) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network("slaves:\n  - { name: Coupler, device: EK1100 }\n  - { name: DO, device: EL2002 }\n");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    EXPECT_EQ(built.network->slaves[0].device->type.revision_no, 0x00120000u);
    EXPECT_EQ(built.network->slaves[1].device->type.revision_no, 0x00120000u);
}

// A small library: revision 5 (a legacy file) is hidden by revision 1 of a current one; 3 is the
// highest revision nothing hides. The index cache keeps the HideTypes.
std::string device(std::uint32_t revision, const std::string& hides) {
    char identity[64];
    std::snprintf(identity, sizeof identity, "ProductCode=\"#x00000010\" RevisionNo=\"#x%08X\"", revision);
    return "<Device Physics=\"YY\"><Type " + std::string(identity) + ">Alpha</Type>" + hides +
           "<Name>Alpha</Name><Sm StartAddress=\"#x1000\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm></Device>\n";
}
std::string esi_file(const std::string& devices) {
    return "<?xml version=\"1.0\"?>\n<EtherCATInfo><Vendor><Id>#x00000abc</Id><Name>Test</Name></Vendor><Descriptions><Groups/><Devices>\n" +
           devices + "</Devices></Descriptions></EtherCATInfo>\n";
}

TEST(RevisionChoice, AHiddenRevisionIsPassedOverWithAndWithoutTheCache) {
    esi::test::TempDir dir;
    fs::create_directories(dir / "lib");
    esi::test::write_text(dir / "lib" / "current.xml",
                          esi_file(device(1, "<HideType RevisionNo=\"#x00000005\" ProductRevision=\"A-9995\"/>") + device(3, "<HideType RevisionNo=\"#x00000001\"/>")));
    esi::test::write_text(dir / "lib" / "legacy.xml", esi_file(device(5, "")));
    for (int run = 0; run < 3; ++run) {  // no cache, cold cache, warm cache
        SCOPED_TRACE(run);
        const auto r = esi::net::build_library_index({dir / "lib"}, run == 0 ? esi::net::IndexOptions{} : esi::net::IndexOptions{dir / "cache"});
        ASSERT_FALSE(r.diagnostics.has_errors()) << esi::test::diagnostics_text(r.diagnostics);
        if (run == 2) {
            EXPECT_EQ(r.stats.cached, 2u);
        }
        const auto res = esi::net::resolve_device(r.index, DeviceQuery{std::nullopt, std::nullopt, 0x10, std::nullopt}, "n.yaml", {});
        ASSERT_NE(res.device, nullptr);
        EXPECT_EQ(res.device->revision_no, 3u);
        const std::string text = message_and_notes(res.diagnostics);
        EXPECT_NE(text.find("passed over: 0x00000005 is a legacy revision: Alpha (revision 0x00000001) at "), std::string::npos) << text;
        EXPECT_NE(text.find("current.xml:3 lists it as a HideType"), std::string::npos) << text;
    }
}

TEST(RevisionChoice, WhenEveryRevisionIsHiddenTheHighestIsTaken) {
    esi::test::TempDir dir;
    fs::create_directories(dir / "lib");
    esi::test::write_text(dir / "lib" / "a.xml", esi_file(device(1, "<HideType RevisionNo=\"#x00000002\"/>") +
                                                           device(2, "<HideType RevisionNo=\"#x00000001\"/>")));
    const auto r = esi::net::build_library_index({dir / "lib"}, {});
    const auto res = esi::net::resolve_device(r.index, DeviceQuery{std::nullopt, std::nullopt, 0x10, std::nullopt}, "n.yaml", {});
    ASSERT_NE(res.device, nullptr);
    EXPECT_EQ(res.device->revision_no, 2u);
}

}  // namespace
