// The ESI library index and its cache, and device resolution.

#include <gtest/gtest.h>

#include <fstream>

#include "esi/net/library_index.hpp"
#include "esi/net/resolve.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::net::build_library_index;
using esi::net::IndexOptions;

std::string esi_file(std::uint32_t product, std::uint32_t revision, const std::string& type) {
    char identity[96];
    std::snprintf(identity, sizeof identity, "ProductCode=\"#x%08X\" RevisionNo=\"#x%08X\"", product, revision);
    return "<?xml version=\"1.0\"?>\n<EtherCATInfo><Vendor><Id>#x00000abc</Id><Name>Test</Name></Vendor><Descriptions><Groups/><Devices>\n"
           "<Device Physics=\"YY\"><Type " +
           std::string(identity) + ">" + type + "</Type><Name>" + type +
           " device</Name><Sm StartAddress=\"#x1000\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm></Device>\n</Devices></Descriptions></EtherCATInfo>\n";
}

struct Library {
    esi::test::TempDir dir;
    Library() {
        fs::create_directories(dir / "lib" / "sub");
        esi::test::write_text(dir / "lib" / "a.xml", esi_file(0x10, 1, "Alpha"));
        esi::test::write_text(dir / "lib" / "sub" / "b.xml", esi_file(0x10, 3, "Alpha"));
        esi::test::write_text(dir / "lib" / "sub" / "c.XML", esi_file(0x20, 1, "Beta"));
        esi::test::write_text(dir / "lib" / "notes.txt", "not an ESI file");
    }
    std::vector<fs::path> roots() const { return {dir / "lib"}; }
    IndexOptions cached() const { return IndexOptions{dir / "cache"}; }
};

TEST(LibraryIndex, FindsEveryXmlFileBelowAFolderInPathOrder) {
    Library lib;
    const esi::net::IndexResult r = build_library_index(lib.roots(), {});
    ASSERT_FALSE(r.diagnostics.has_errors()) << esi::test::diagnostics_text(r.diagnostics);
    ASSERT_EQ(r.index.files.size(), 3u);
    EXPECT_NE(r.index.files[0].path.find("a.xml"), std::string::npos);
    ASSERT_EQ(r.index.devices.size(), 3u);
    EXPECT_EQ(r.index.devices[0].type, "Alpha");
    EXPECT_EQ(r.index.devices[0].vendor_id, 0xABCu);
    EXPECT_EQ(r.index.devices[0].line, 3u);
    EXPECT_GT(r.index.devices[0].offset, 0u);
}

TEST(LibraryIndex, CacheRescansOnlyChangedFiles) {
    Library lib;
    const auto first = build_library_index(lib.roots(), lib.cached());
    EXPECT_EQ(first.stats.scanned, 3u);
    EXPECT_TRUE(first.stats.cache_written);
    EXPECT_TRUE(fs::exists(esi::net::index_cache_file(lib.dir / "cache")));

    const auto warm = build_library_index(lib.roots(), lib.cached());
    EXPECT_EQ(warm.stats.scanned, 0u);
    EXPECT_EQ(warm.stats.cached, 3u);
    EXPECT_FALSE(warm.stats.cache_written);
    ASSERT_EQ(warm.index.devices.size(), first.index.devices.size());
    for (std::size_t i = 0; i < warm.index.devices.size(); ++i) {
        EXPECT_EQ(warm.index.devices[i].type, first.index.devices[i].type);
        EXPECT_EQ(warm.index.devices[i].revision_no, first.index.devices[i].revision_no);
        EXPECT_EQ(warm.index.devices[i].offset, first.index.devices[i].offset);
    }

    // A changed file (new size) is scanned again; the others come from the cache.
    esi::test::write_text(lib.dir / "lib" / "a.xml", esi_file(0x10, 2, "Alpha-renamed"));
    const auto changed = build_library_index(lib.roots(), lib.cached());
    EXPECT_EQ(changed.stats.scanned, 1u);
    EXPECT_EQ(changed.stats.cached, 2u);
    EXPECT_EQ(changed.index.devices[0].type, "Alpha-renamed");
}

TEST(LibraryIndex, ADamagedCacheIsIgnoredAndRebuilt) {
    Library lib;
    (void)build_library_index(lib.roots(), lib.cached());
    const fs::path cache = esi::net::index_cache_file(lib.dir / "cache");
    std::string text = esi::test::read_text(cache);
    for (const std::string& damaged : {text.substr(0, text.size() / 2), std::string("garbage\n"), text + "D 1 2 3\n",
                                       std::string("libesi-esi-index 1\nF 1 2 1 /x\nend 1\n")}) {
        esi::test::write_text(cache, damaged);
        const auto r = build_library_index(lib.roots(), lib.cached());
        EXPECT_TRUE(r.stats.cache_ignored);
        EXPECT_EQ(r.stats.scanned, 3u);
        EXPECT_EQ(r.index.devices.size(), 3u);
        EXPECT_TRUE(r.stats.cache_written);
        EXPECT_FALSE(r.diagnostics.has_errors());
    }
    const auto again = build_library_index(lib.roots(), lib.cached());
    EXPECT_FALSE(again.stats.cache_ignored);
    EXPECT_EQ(again.stats.scanned, 0u);
}

TEST(LibraryIndex, AnUnwritableCacheOnlyWarns) {
    Library lib;
    esi::test::write_text(lib.dir / "cache", "a file where the cache folder should be");
    const auto r = build_library_index(lib.roots(), lib.cached());
    EXPECT_FALSE(r.diagnostics.has_errors());
    EXPECT_FALSE(r.stats.cache_written);
    EXPECT_EQ(r.index.devices.size(), 3u);
    EXPECT_EQ(r.diagnostics.count(esi::Severity::warning), 1u) << esi::test::diagnostics_text(r.diagnostics);
}

TEST(LibraryIndex, AMissingRootIsAnErrorAndABrokenFileAWarning) {
    Library lib;
    esi::test::write_text(lib.dir / "lib" / "broken.xml", "<EtherCATInfo><Descriptions><Devices><Device>");
    const auto r = build_library_index({lib.dir / "lib", lib.dir / "nowhere"}, {});
    EXPECT_TRUE(r.diagnostics.has_errors());
    const std::string text = esi::test::diagnostics_text(r.diagnostics);
    EXPECT_NE(text.find("nowhere"), std::string::npos) << text;
    EXPECT_NE(text.find("broken.xml: warning: not indexed"), std::string::npos) << text;
    EXPECT_EQ(r.index.devices.size(), 3u);
}

TEST(Resolve, HighestRevisionWithANoteWhenNoneIsGiven) {
    Library lib;
    const auto r = build_library_index(lib.roots(), {});
    const esi::net::Resolution res = esi::net::resolve_device(r.index, {std::nullopt, std::nullopt, 0x10, std::nullopt}, "n.yaml", {3, 5});
    ASSERT_NE(res.device, nullptr);
    EXPECT_EQ(res.device->revision_no, 3u);
    ASSERT_EQ(res.diagnostics.size(), 1u);
    EXPECT_EQ(res.diagnostics.items()[0].severity, esi::Severity::info);
    EXPECT_NE(res.diagnostics.items()[0].message.find("highest, 0x00000003, of 2"), std::string::npos);
}

TEST(Resolve, UnknownRevisionNamesTheNearestAndWhereItLooked) {
    Library lib;
    const auto r = build_library_index(lib.roots(), {});
    const esi::net::Resolution res = esi::net::resolve_device(r.index, {std::nullopt, std::nullopt, 0x10, 2}, "n.yaml", {3, 5});
    ASSERT_EQ(res.device, nullptr);
    ASSERT_EQ(res.diagnostics.size(), 1u);
    const esi::Diagnostic& d = res.diagnostics.items()[0];
    EXPECT_EQ(d.rule, "net-device-unknown");
    EXPECT_EQ(d.pos.line, 3u);
    EXPECT_NE(d.message.find("looked in"), std::string::npos);
    EXPECT_NE(d.message.find("3 files, 3 devices"), std::string::npos) << d.message;
    ASSERT_EQ(d.notes.size(), 2u);
    EXPECT_NE(d.notes[0].message.find("revision 0x00000001"), std::string::npos);  // 1 and 3 are equally near; 1 is listed first
    EXPECT_NE(d.notes[0].path.find("a.xml"), std::string::npos);
}

TEST(Resolve, ANameSuggestsCloseTypeTexts) {
    Library lib;
    const auto r = build_library_index(lib.roots(), {});
    const esi::net::Resolution res = esi::net::resolve_device(r.index, {"Alpah", std::nullopt, std::nullopt, std::nullopt}, "n.yaml", {});
    ASSERT_EQ(res.device, nullptr);
    const esi::Diagnostic& d = res.diagnostics.items()[0];
    ASSERT_FALSE(d.notes.empty());
    EXPECT_NE(d.notes[0].message.find("nearest: Alpha"), std::string::npos);
    // Case does not matter when the name is otherwise exact.
    EXPECT_NE(esi::net::resolve_device(r.index, {"alpha", std::nullopt, std::nullopt, std::nullopt}, "n.yaml", {}).device, nullptr);
}

TEST(Resolve, ANameSeveralProductsCarryIsAmbiguous) {
    Library lib;
    esi::test::write_text(lib.dir / "lib" / "d.xml", esi_file(0x30, 1, "Beta"));
    const auto r = build_library_index(lib.roots(), {});
    const esi::net::Resolution res = esi::net::resolve_device(r.index, {"Beta", std::nullopt, std::nullopt, std::nullopt}, "n.yaml", {});
    ASSERT_EQ(res.device, nullptr);
    const esi::Diagnostic& d = res.diagnostics.items()[0];
    EXPECT_EQ(d.rule, "net-device-ambiguous");
    EXPECT_EQ(d.notes.size(), 2u);
}

TEST(Resolve, FindQueries) {
    std::string error;
    auto q = esi::net::parse_find_query("2:0x07D83052:#x00120000", error);
    ASSERT_TRUE(q);
    EXPECT_EQ(q->vendor_id, 2u);
    EXPECT_EQ(q->product_code, 0x07D83052u);
    EXPECT_EQ(q->revision_no, 0x00120000u);
    q = esi::net::parse_find_query("0x1000", error);
    ASSERT_TRUE(q);
    EXPECT_EQ(q->product_code, 0x1000u);
    EXPECT_FALSE(q->vendor_id);
    q = esi::net::parse_find_query("EL2008", error);
    ASSERT_TRUE(q);
    EXPECT_EQ(q->name, "EL2008");
    EXPECT_FALSE(esi::net::parse_find_query("2:0xZZ", error));
    EXPECT_FALSE(esi::net::parse_find_query("", error));
}

TEST(EsiNetFind, ListsEveryRevisionInTheCorpusAndExitsOneWhenNothingMatches) {
    ESI_REQUIRE_CORPUS();
    esi::test::TempDir home;
    const auto found = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "find", "--esi", esi::test::corpus_esi_dir().string(), "EL2008"});
    EXPECT_EQ(found.exit_code, 0) << found.err;
    EXPECT_NE(found.out.find("Beckhoff__EL2xxx__dls-ethercat.xml:"), std::string::npos) << found.out;
    EXPECT_NE(found.out.find("revision 0x00120000"), std::string::npos) << found.out;
    const auto missing =
        esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "find", "--esi", esi::test::corpus_esi_dir().string(), "2:0x07D83052:7"});
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.err.find("nearest: EL2008"), std::string::npos) << missing.err;
    const auto usage = esi::test::run({esi::test::tool("esi-net").string(), "find", "EL2008"});
    EXPECT_EQ(usage.exit_code, 2);
}

}  // namespace
