// The library index cache is an optimisation that never changes a result (issue 27, item 5):
// a file changed without changing its size and time, an edited cache, a FIFO in the cache's
// place, and identities written with character references.

#include <gtest/gtest.h>

#include <sys/stat.h>

#include "esi/net/library_index.hpp"
#include "esi/net/network_spec.hpp"
#include "esi/net/resolve.hpp"
#include "net/hostile_esi.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::net::build_library_index;

esi::test::HostileDevice device_with(const std::string& vendor, const std::string& product) {
    esi::test::HostileDevice d;
    d.vendor_id = vendor;
    d.product_code = product;
    return d;
}

// Rewrites `file` with `text` (same length) and gives it back its size and modification time,
// as `cp -p` or `touch -r` do.
void replace_keeping_size_and_time(const fs::path& file, const std::string& text) {
    const auto time = fs::last_write_time(file);
    ASSERT_EQ(fs::file_size(file), text.size());
    esi::test::write_text(file, text);
    fs::last_write_time(file, time);
}

TEST(IndexCacheTrust, AFileChangedUnderTheSameSizeAndTimeIsIndexedAnew) {
    esi::test::TempDir dir;
    const fs::path file = dir / "lib.xml";
    esi::test::write_text(file, device_with("#x00000ABC", "#x00001002").xml());
    const esi::net::IndexOptions cached{dir / "cache"};
    ASSERT_EQ(build_library_index({file}, cached).index.devices.at(0).product_code, 0x1002u);
    replace_keeping_size_and_time(file, device_with("#x00000ABD", "#x00001003").xml());
    const auto r = build_library_index({file}, cached);
    ASSERT_FALSE(r.index.devices.empty());
    EXPECT_EQ(r.index.devices[0].product_code, 0x1003u);
    EXPECT_EQ(r.index.devices[0].vendor_id, 0xABDu);
}

TEST(IndexCacheTrust, BuildResolvesAgainstTheFileNotTheCachedVendor) {
    esi::test::TempDir dir;
    const fs::path file = dir / "lib.xml";
    esi::test::write_text(file, device_with("#x00000ABC", "#x00001002").xml());
    const esi::net::IndexOptions cached{dir / "cache"};
    (void)build_library_index({file}, cached);
    replace_keeping_size_and_time(file, device_with("#x00000ABD", "#x00001002").xml());
    esi::net::BuildOptions options;
    options.extra_esi = {file};
    options.index = cached;
    auto build = [&](const std::string& slave) {
        const esi::net::NetworkFileResult read = esi::net::read_network_text("slaves:\n  - " + slave + "\n", (dir / "n.yaml").string());
        EXPECT_TRUE(read.spec);
        return esi::net::build_network(*read.spec, options);
    };
    // Vendor 0xABC is no longer in the library: no configuration for it, whatever the cache says.
    const esi::net::BuildResult old_vendor = build("{ name: D, vendor_id: 0xABC, product_code: 0x1002 }");
    EXPECT_FALSE(old_vendor.network) << esi::test::diagnostics_text(old_vendor.diagnostics);
    // The file's vendor builds, twice in a row: no "run again" that repeats forever.
    for (int run = 0; run < 2; ++run) {
        const esi::net::BuildResult built = build("{ name: D, vendor_id: 0xABD, product_code: 0x1002 }");
        ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
        EXPECT_EQ(built.network->slaves.at(0).vendor_id, 0xABDu);
    }
}

TEST(IndexCacheTrust, AnEditedButWellFormedCacheIsNotTrusted) {
    esi::test::TempDir dir;
    const fs::path file = dir / "lib.xml";
    esi::test::write_text(file, device_with("#x00000ABC", "#x00001002").xml());
    const esi::net::IndexOptions cached{dir / "cache"};
    (void)build_library_index({file}, cached);
    const fs::path cache = esi::net::index_cache_file(dir / "cache");
    std::string text = esi::test::read_text(cache);
    const std::size_t at = text.find("D 2748 4098 ");  // vendor 0xABC, product 0x1002, in decimal
    ASSERT_NE(at, std::string::npos) << text;
    text.replace(at, 12, "D 2748 4099 ");
    esi::test::write_text(cache, text);
    const auto r = build_library_index({file}, cached);
    ASSERT_FALSE(r.index.devices.empty());
    EXPECT_EQ(r.index.devices[0].product_code, 0x1002u);
}

TEST(IndexCacheTrust, AFifoInTheCachesPlaceDoesNotHang) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "lib.xml", esi::test::HostileDevice{}.xml());
    fs::create_directories(dir / "cache" / "libesi");
    ASSERT_EQ(::mkfifo(esi::net::index_cache_file(dir / "cache" / "libesi").c_str(), 0600), 0);
    const auto r = esi::test::run({"env", "XDG_CACHE_HOME=" + (dir / "cache").string(), "timeout", "20",
                                   esi::test::tool("esi-net").string(), "find", "--esi", (dir / "lib.xml").string(), "Hostile"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Hostile"), std::string::npos) << r.out;
}

TEST(IndexCacheTrust, AFifoAmongTheLibraryFilesIsNotOpened) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "lib.xml", esi::test::HostileDevice{}.xml());
    ASSERT_EQ(::mkfifo((dir / "pipe.xml").c_str(), 0600), 0);
    const auto r = esi::test::run({"timeout", "20", esi::test::tool("esi-net").string(), "--no-cache", "find", "--esi",
                                   (dir / "lib.xml").string(), "--esi", (dir / "pipe.xml").string(), "Hostile"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(IndexCacheTrust, ACharacterReferenceInTheProductCodeIsFoundAsTheReaderReadsIt) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "lib.xml", device_with("#x00000ABC", "&#35;x00001003").xml());
    const auto r = build_library_index({dir / "lib.xml"}, {});
    ASSERT_FALSE(r.index.devices.empty()) << esi::test::diagnostics_text(r.diagnostics);
    EXPECT_EQ(r.index.devices[0].product_code, 0x1003u);
    const esi::net::Resolution res = esi::net::resolve_device(r.index, {std::nullopt, std::nullopt, 0x1003, std::nullopt}, "n.yaml", {});
    EXPECT_NE(res.device, nullptr);
}

}  // namespace
