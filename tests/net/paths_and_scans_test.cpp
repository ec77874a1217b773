// Paths, scans and sizes (issue 27, item 7): init writes `esi:` relative to the network file, a
// .xml file that is not XML is reported, a scan that cannot be the bus (an alias beyond 16 bits,
// a position twice, a cut last block) is refused with file:line, and a network is capped at
// what one EtherCAT segment can address.

#include <gtest/gtest.h>

#include "esi/net/igh_scan.hpp"
#include "esi/net/library_index.hpp"
#include "esi/net/network_spec.hpp"
#include "net/hostile_esi.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

std::string block(unsigned position, const std::string& alias = "0") {
    return "=== Master 0, Slave " + std::to_string(position) + " ===\nAlias: " + alias +
           "\nIdentity:\n  Vendor Id:       0x00000abc\n  Product code:    0x00001002\n  Revision number: 0x00000001\n"
           "  Serial number:   0x00000000\nGeneral:\n  Device name: Hostile\n";
}

TEST(PathsAndScans, InitWritesEsiPathsRelativeToTheNetworkFile) {
    esi::test::TempDir dir;
    fs::create_directories(dir / "lib");
    fs::create_directories(dir / "net");
    esi::test::write_text(dir / "lib" / "dev.xml", esi::test::HostileDevice{}.xml());
    esi::test::write_text(dir / "scan.txt", block(0));
    const std::string net = esi::test::tool("esi-net").string();
    const auto init = esi::test::run({net, "--no-cache", "init", "--from-igh", "scan.txt", "--esi", "lib", "-o", "net/network.yaml"}, {}, dir.path());
    ASSERT_EQ(init.exit_code, 0) << init.err;
    const auto build = esi::test::run({net, "--no-cache", "build", "net/network.yaml", "-o", "out"}, {}, dir.path());
    EXPECT_EQ(build.exit_code, 0) << esi::test::read_text(dir / "net" / "network.yaml") << build.err;
}

TEST(PathsAndScans, AnXmlFileThatIsNotXmlIsReported) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "notes.xml", "just some notes, not XML\n");
    const auto r = esi::net::build_library_index({dir / "notes.xml"}, {});
    const std::string text = esi::test::diagnostics_text(r.diagnostics);
    EXPECT_NE(text.find("net-index"), std::string::npos) << text;
    EXPECT_NE(text.find("notes.xml"), std::string::npos) << text;
}

std::string scan_errors(const std::string& text) {
    const esi::net::IghScan scan = esi::net::parse_igh_slaves(text, "scan.txt");
    std::string out;
    for (const esi::Diagnostic& d : scan.diagnostics)
        if (d.severity == esi::Severity::error) out += esi::format_diagnostic(d);
    return out;
}

TEST(PathsAndScans, AnAliasBeyond16BitsIsRefused) {
    const std::string errors = scan_errors(block(0, "70000"));
    EXPECT_NE(errors.find("scan.txt:2:"), std::string::npos) << errors;
}

TEST(PathsAndScans, APositionTwiceIsRefused) {
    const std::string errors = scan_errors(block(0) + block(1) + block(1));
    EXPECT_NE(errors.find("scan.txt:19:"), std::string::npos) << errors;
}

TEST(PathsAndScans, ABlockHeaderWhoseNumbersDoNotFit32BitsIsRefusedNotWrapped) {
    // sscanf's %u read master 4294967296 as master 0 and "#x" made the header an ordinary line,
    // so that block's identity overwrote the one before it.
    for (const std::string header : {"=== Master 4294967296, Slave 1 ===", "=== Master #x, Slave 1 ===", "=== Master 0, Slave -1 ==="}) {
        std::string text = block(0) + block(1);
        text.replace(text.find("=== Master 0, Slave 1 ==="), 25, header);
        const std::string errors = scan_errors(text);
        EXPECT_NE(errors.find("scan.txt:10:"), std::string::npos) << header << "\n" << errors;
    }
}

TEST(PathsAndScans, ACutLastBlockIsRefused) {
    std::string text = block(0) + block(1);
    text.resize(text.find("Product code", text.find("Slave 1")) + 22);  // "Product code:    0x000" and no more
    const std::string errors = scan_errors(text);
    EXPECT_FALSE(errors.empty()) << text;
    EXPECT_NE(errors.find("scan.txt:"), std::string::npos) << errors;
}

TEST(PathsAndScans, ANetworkBeyondWhatASegmentAddressesIsRefused) {
    esi::net::NetworkSpec spec;
    spec.path = "n.yaml";
    spec.slaves.resize(64536);
    for (esi::net::SlaveSpec& s : spec.slaves) s.device = "X";
    const esi::net::BuildResult built = esi::net::build_network(spec, esi::net::LibraryIndex{});
    EXPECT_FALSE(built.network);
    ASSERT_FALSE(built.diagnostics.items().empty());
    EXPECT_EQ(built.diagnostics.items().front().rule, "net-too-many-slaves") << esi::test::diagnostics_text(built.diagnostics).substr(0, 500);
}

}  // namespace
