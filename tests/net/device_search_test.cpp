// `esi-net find` by partial name and by vendor (issue 24 §4): `find SV660` finds InoSV660N,
// `find --vendor Elmo` lists Elmo's devices, ranked exact > prefix > substring > fuzzy, each with
// the file:line of its Device element; text and JSON.

#include <gtest/gtest.h>

#include "esi/net/device_search.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::net::MatchRank;

esi::net::DeviceSearch search(const std::string& name, std::optional<std::string> vendor = std::nullopt) {
    std::optional<esi::net::DeviceQuery> q;
    if (!name.empty()) {
        std::string error;
        q = esi::net::parse_find_query(name, error);
    }
    return esi::net::search_devices(esi::test::corpus_index(), q, vendor);
}

TEST(DeviceSearch, APartOfTheTypeTextFindsTheDeviceWithItsFileAndLine) {
    ESI_REQUIRE_CORPUS();
    const esi::net::DeviceSearch found = search("SV660");
    ASSERT_EQ(found.matches.size(), 1u) << esi::net::device_search_text(esi::test::corpus_index(), found);
    const esi::net::IndexedDevice& d = *found.matches[0].device;
    EXPECT_EQ(d.type, "InoSV660N");
    EXPECT_EQ(found.matches[0].rank, MatchRank::substring);
    const std::string text = esi::net::device_search_text(esi::test::corpus_index(), found);
    EXPECT_NE(text.find("Inovance__SV660_EOE_1Axis_V9.12__hw_device_mgr__2021-09.xml:20:7:"), std::string::npos) << text;
    EXPECT_NE(text.find("[substring]"), std::string::npos) << text;
}

TEST(DeviceSearch, ByVendorNameListsEveryDeviceOfThatVendor) {
    ESI_REQUIRE_CORPUS();
    const esi::net::DeviceSearch found = search("", "elmo");
    std::size_t elmo = 0;
    for (const esi::net::IndexedDevice& d : esi::test::corpus_index().devices) elmo += d.vendor_id == 0x9Au;
    ASSERT_GT(elmo, 0u);
    EXPECT_EQ(found.matches.size(), elmo);
    for (const esi::net::DeviceMatch& m : found.matches) {
        EXPECT_EQ(m.device->vendor_id, 0x9Au);
        EXPECT_EQ(m.device->vendor_name, "Elmo Motion Control");
        EXPECT_EQ(m.rank, MatchRank::vendor);
    }
    // By id as well, and combined with a name.
    EXPECT_EQ(search("", "0x9A").matches.size(), elmo);
    EXPECT_TRUE(search("EK1100", "Elmo").matches.empty());
    EXPECT_TRUE(search("EK1100", "Elmo").diagnostics.has_errors());
    EXPECT_FALSE(search("EK1100", "Beckhoff").matches.empty());
}

TEST(DeviceSearch, RanksExactThenPrefixThenSubstring) {
    ESI_REQUIRE_CORPUS();
    const esi::net::DeviceSearch found = search("ek110");
    ASSERT_FALSE(found.matches.empty());
    bool prefix = false;
    for (std::size_t i = 0; i < found.matches.size(); ++i) {
        if (i > 0) {
            EXPECT_LE(found.matches[i - 1].rank, found.matches[i].rank);
        }
        prefix = prefix || (found.matches[i].rank == MatchRank::prefix && found.matches[i].device->type == "EK1100");
    }
    EXPECT_TRUE(prefix);
    const esi::net::DeviceSearch el2008 = search("EL2008");
    ASSERT_FALSE(el2008.matches.empty());
    EXPECT_EQ(el2008.matches.front().rank, MatchRank::exact);
    EXPECT_EQ(el2008.matches.front().device->type, "EL2008");
    // Within a rank: by Type text, the highest revision first.
    EXPECT_EQ(el2008.matches.front().device->revision_no, 0x00120000u);
    for (const esi::net::DeviceMatch& m : el2008.matches) EXPECT_NE(m.rank, MatchRank::fuzzy);
}

TEST(DeviceSearch, LegacyRevisionsComeAfterTheCurrentOnesAndSaySo) {
    ESI_REQUIRE_CORPUS();
    const esi::net::DeviceSearch found = search("EK1100");
    ASSERT_FALSE(found.matches.empty());
    // The first line is what `build` takes without a revision, not the legacy 0x270B0000.
    EXPECT_EQ(found.matches.front().device->revision_no, 0x00120000u);
    EXPECT_EQ(found.matches.front().hidden_by, nullptr);
    bool legacy = false;
    for (const esi::net::DeviceMatch& m : found.matches)
        if (m.device->type == "EK1100" && m.device->revision_no == 0x270B0000u) legacy = m.hidden_by != nullptr;
    EXPECT_TRUE(legacy);
    const std::string text = esi::net::device_search_text(esi::test::corpus_index(), found);
    EXPECT_NE(text.find("revision 0x270B0000) — EK1100 Ethernet Coupler Terminal [exact; hidden by EK1100 revision 0x00000000]"),
              std::string::npos)
        << text;
}

TEST(DeviceSearch, ATypoFindsFuzzyMatchesOnlyWhenNothingContainsTheText) {
    ESI_REQUIRE_CORPUS();
    const esi::net::DeviceSearch found = search("EL2O08");
    ASSERT_FALSE(found.matches.empty());
    bool el2008 = false;
    for (const esi::net::DeviceMatch& m : found.matches) {
        EXPECT_EQ(m.rank, MatchRank::fuzzy);
        el2008 = el2008 || m.device->type == "EL2008";
    }
    EXPECT_TRUE(el2008);
    EXPECT_TRUE(search("NoSuchDeviceAnywhere").matches.empty());
    EXPECT_TRUE(search("NoSuchDeviceAnywhere").diagnostics.has_errors());
}

TEST(DeviceSearch, TheVendorNameSurvivesTheIndexCache) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "a.xml",
                          "<?xml version=\"1.0\"?>\n<EtherCATInfo><Vendor><Id>7</Id><Name LcId=\"1031\">Firma</Name><Name LcId=\"1033\">Acme\tWorks</Name>"
                          "</Vendor><Descriptions><Groups/><Devices>\n<Device><Type ProductCode=\"#x1\" RevisionNo=\"#x2\">Widget</Type><Name>W</Name>"
                          "</Device>\n</Devices></Descriptions></EtherCATInfo>\n");
    for (int run = 0; run < 2; ++run) {
        const auto r = esi::net::build_library_index({dir / "a.xml"}, esi::net::IndexOptions{dir / "cache"});
        ASSERT_EQ(r.index.devices.size(), 1u);
        EXPECT_EQ(r.index.devices[0].vendor_name, "Acme\tWorks");
        EXPECT_EQ(r.stats.cached, run == 0 ? 0u : 1u);
        EXPECT_EQ(esi::net::search_devices(r.index, std::nullopt, std::string("acme")).matches.size(), 1u);
    }
}

TEST(EsiNetFindCli, PartialNamesVendorsAndJson) {
    ESI_REQUIRE_CORPUS();
    const std::string esi_net = esi::test::tool("esi-net").string(), lib = esi::test::corpus_esi_dir().string();
    const auto sv = esi::test::run({esi_net, "--no-cache", "find", "--esi", lib, "SV660"});
    EXPECT_EQ(sv.exit_code, 0) << sv.err;
    EXPECT_NE(sv.out.find("InoSV660N"), std::string::npos) << sv.out;
    const auto elmo = esi::test::run({esi_net, "--no-cache", "find", "--esi", lib, "--vendor", "Elmo", "--format", "json"});
    EXPECT_EQ(elmo.exit_code, 0) << elmo.err;
    EXPECT_EQ(elmo.out.rfind("{\n  \"devices\": [\n    {\n      \"match\": \"vendor\",\n      \"type\": \"Elmo Drive\",", 0), 0u) << elmo.out;
    EXPECT_NE(elmo.out.find("\"vendor\": \"Elmo Motion Control\""), std::string::npos);
    EXPECT_NE(elmo.out.find("\"file\": \"" + lib + "/Elmo__ECAT_00010420_V11__hw_device_mgr.xml\""), std::string::npos) << elmo.out;
    const auto again = esi::test::run({esi_net, "--no-cache", "find", "--esi", lib, "--vendor", "Elmo", "--format", "json"});
    EXPECT_EQ(again.out, elmo.out);
    EXPECT_EQ(esi::test::run({esi_net, "--no-cache", "find", "--esi", lib}).exit_code, 2);
    EXPECT_EQ(esi::test::run({esi_net, "--no-cache", "find", "--esi", lib, "--format", "xml", "EL2008"}).exit_code, 2);
    EXPECT_EQ(esi::test::run({esi_net, "--no-cache", "find", "--esi", lib, "--vendor", "Nobody"}).exit_code, 1);
}

}  // namespace
