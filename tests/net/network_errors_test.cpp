// Bad input to esi-net: every problem is a located diagnostic with its rule id, no network is
// built, and the tool writes nothing and exits 1 (network errors) or 2 (unreadable or invalid
// NETWORK.yaml, usage).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "esi/net/network_spec.hpp"
#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

// The rules of the errors a YAML text produces when read.
std::vector<std::string> read_errors(const std::string& yaml, std::string* text = nullptr) {
    const esi::net::NetworkFileResult r = esi::net::read_network_text(yaml, "n.yaml");
    std::vector<std::string> rules;
    for (const esi::Diagnostic& d : r.diagnostics)
        if (d.severity == esi::Severity::error) rules.push_back(d.rule);
    if (text) *text = esi::test::diagnostics_text(r.diagnostics);
    EXPECT_EQ(r.spec.has_value(), rules.empty());
    return rules;
}

// The rules of the errors building a network over the corpus gives; the network is not built.
std::vector<std::string> build_errors(const std::string& yaml, std::string* text = nullptr) {
    const esi::net::BuildResult built = esi::test::build_corpus_network(yaml);
    std::vector<std::string> rules;
    for (const esi::Diagnostic& d : built.diagnostics)
        if (d.severity == esi::Severity::error) rules.push_back(d.rule);
    if (text) *text = esi::test::diagnostics_text(built.diagnostics);
    EXPECT_EQ(built.network.has_value(), rules.empty());
    return rules;
}

using ::testing::Contains;
using ::testing::ElementsAre;

TEST(NetworkFile, UnknownKeysSuggestTheClosestWithTheirPosition) {
    std::string text;
    EXPECT_THAT(read_errors("slaves:\n  - { name: a, prodct_code: 0x10 }\n", &text), Contains("yaml-unknown-key"));
    EXPECT_NE(text.find("n.yaml:2:16: error: unknown key 'prodct_code' in a slave; did you mean 'product_code'?"), std::string::npos) << text;
    EXPECT_THAT(read_errors("master: { cycle_time: 1000 }\nslaves: []\n", &text), ElementsAre("yaml-unknown-key"));
    EXPECT_NE(text.find("did you mean 'cycle_time_us'?"), std::string::npos) << text;
}

TEST(NetworkFile, DuplicateKeysAndWrongShapesAreLocated) {
    std::string text;
    EXPECT_THAT(read_errors("slaves:\n  - name: a\n    name: b\n    device: X\n", &text), Contains("yaml-duplicate-key"));
    EXPECT_NE(text.find("n.yaml:3:5"), std::string::npos) << text;
    EXPECT_THAT(read_errors("master: {}\n"), ElementsAre("yaml-missing-key"));
    EXPECT_THAT(read_errors("slaves: { a: 1 }\n"), ElementsAre("yaml-type"));
    EXPECT_THAT(read_errors("slaves:\n  - { name: a }\n"), ElementsAre("yaml-missing-key"));
    EXPECT_THAT(read_errors("slaves:\n  - { device: X, pdos: [0x2000] }\n"), ElementsAre("yaml-number-range"));
    EXPECT_THAT(read_errors("slaves:\n  - { device: X, pdo_entries: { 0x1600: [0x6040-0-16] } }\n", &text), ElementsAre("yaml-type"));
    EXPECT_NE(text.find("INDEX:SUBINDEX:BITLEN"), std::string::npos);
    EXPECT_THAT(read_errors("slaves:\n  - { device: X, pdos: [0x1600], pdo_mapping: Standard }\n"), ElementsAre("net-pdo-selection"));
    EXPECT_THAT(read_errors("slaves:\n  - { name: a, device: X }\n  - { name: a, device: Y }\n"), ElementsAre("net-duplicate-name"));
    EXPECT_THAT(read_errors("slaves:\n  - { device: X, sdos: [{ index: 0x6060, value: 1, data: '01' }] }\n"), ElementsAre("net-sdo-value"));
    EXPECT_THAT(read_errors("slaves:\n  - { device: X, sdos: [{ index: 0x6060, value: 1, transition: XS }] }\n"), ElementsAre("net-transition"));
    EXPECT_THAT(read_errors("master: { source_mac: 0102 }\nslaves: []\n"), ElementsAre("yaml-type"));
    EXPECT_THAT(read_errors(""), ElementsAre("yaml-empty"));
    EXPECT_THAT(read_errors("slaves: [ {"), Contains("yaml-syntax"));
}

TEST(NetworkBuild, AnUnknownIdentityNamesTheNearestRevisions) {
    ESI_REQUIRE_CORPUS();
    std::string text;
    EXPECT_THAT(build_errors("slaves:\n  - { name: Out, product_code: 0x07D83052, revision: 0x00130000 }\n", &text),
                ElementsAre("net-device-unknown"));
    EXPECT_NE(text.find("network.yaml:2:32: error: no ESI file describes product code 0x07D83052, revision 0x00130000; looked in"), std::string::npos)
        << text;
    EXPECT_NE(text.find("Beckhoff__EL2xxx__dls-ethercat.xml:"), std::string::npos) << text;
    EXPECT_NE(text.find("note: nearest: EL2008 (vendor 0x00000002, product code 0x07D83052, revision 0x00120000)"), std::string::npos) << text;
}

TEST(NetworkBuild, AnAmbiguousNameListsTheCandidates) {
    ESI_REQUIRE_CORPUS();
    std::string text;
    // Two Elmo products carry the Type text "Elmo Drive ".
    EXPECT_THAT(build_errors("slaves:\n  - { device: Elmo Drive }\n", &text), ElementsAre("net-device-ambiguous"));
    EXPECT_NE(text.find("product code 0x00030924"), std::string::npos) << text;
    EXPECT_NE(text.find("product code 0x00030925"), std::string::npos) << text;
}

constexpr const char* elmo = "product_code: 0x00030924, revision: 0x00010420";

TEST(NetworkBuild, PdoSelectionsTheEsiForbids) {
    ESI_REQUIRE_CORPUS();
    std::string text;
    // 0x1600 excludes 0x1601.
    EXPECT_THAT(build_errors(std::string("slaves:\n  - { ") + elmo + ", pdos: [0x1600, 0x1601, 0x1A00] }\n", &text), ElementsAre("net-pdo-exclude"));
    EXPECT_NE(text.find("0x1600 and 0x1601 exclude each other"), std::string::npos) << text;
    // More than SM2's MaxSize (32 bytes).
    EXPECT_THAT(build_errors(std::string("slaves:\n  - { ") + elmo +
                             ", pdos: [0x160F, 0x1611, 0x1612, 0x1613, 0x1614, 0x1615, 0x1616, 0x1617, 0x161C, 0x1A00] }\n",
                             &text),
                Contains("net-sm-size"));
    EXPECT_NE(text.find("the ESI allows at most 32 (MaxSize)"), std::string::npos) << text;
    // Unknown PDO index: the device's PDOs are listed.
    EXPECT_THAT(build_errors(std::string("slaves:\n  - { ") + elmo + ", pdos: [0x1777] }\n", &text), ElementsAre("net-pdo-unknown"));
    EXPECT_NE(text.find("has no RxPDO 0x1777; its RxPDOs: 0x1600, 0x1601"), std::string::npos) << text;
    // EL2008 has no mailbox: its assignment is fixed, and its PDOs are Mandatory.
    EXPECT_THAT(build_errors("slaves:\n  - { product_code: 0x07D83052, revision: 0x00120000, pdos: [0x1600] }\n", &text),
                Contains("net-pdo-fixed-assignment"));
    EXPECT_THAT(build_errors("slaves:\n  - { product_code: 0x07D83052, revision: 0x00120000, pdos: [0x1600] }\n"), Contains("net-pdo-mandatory"));
    EXPECT_NE(text.find("always assigns: 0x1600, 0x1601, 0x1602"), std::string::npos) << text;
    // The device family's limits.
    EXPECT_THAT(build_errors(std::string("slaves:\n  - { ") + elmo + ", pdos: [0x160A, 0x160B, 0x1A0A], limits: { max_pdos: { rx: 1 } } }\n"),
                ElementsAre("net-limit-pdo-count"));
}

TEST(NetworkBuild, NamedMappingsDcOpModesAndModulesMustExist) {
    ESI_REQUIRE_CORPUS();
    std::string text;
    EXPECT_THAT(build_errors(std::string("slaves:\n  - { ") + elmo + ", dc: DC Synch }\n", &text), ElementsAre("net-dc-op-mode"));
    EXPECT_NE(text.find("no DC op mode 'DC Synch'; did you mean 'DC Sync'?; Elmo Drive has 'DC Sync', 'DC Off'"), std::string::npos) << text;
    EXPECT_THAT(build_errors("master: { dc: false }\nslaves:\n  - { " + std::string(elmo) + ", dc: DC Sync }\n"), ElementsAre("net-dc-off"));
    EXPECT_THAT(build_errors("slaves:\n  - { device: ECAT_CIA402, modules: [csv axis] }\n", &text), ElementsAre("net-module"));
    EXPECT_NE(text.find("slot 0 (Axis 0) cannot take module 'csv axis'; it takes: 'csv,csp - axis' (0x119800), 'csp - axis' (0x219800), "
                        "'csv -  axis' (0x319800)"),
              std::string::npos)
        << text;
    EXPECT_THAT(build_errors("slaves:\n  - { device: ECAT_CIA402, modules: [csv -  axis, csv -  axis, csv -  axis] }\n", &text),
                ElementsAre("net-module"));
    EXPECT_NE(text.find("has 2 slot positions; there is no slot 2"), std::string::npos) << text;
    EXPECT_THAT(build_errors("slaves:\n  - { device: ECAT_CIA402, modules: [null] }\n", &text), ElementsAre("net-module"));
    EXPECT_NE(text.find("needs a module (MinInstances 1)"), std::string::npos) << text;
    EXPECT_THAT(build_errors("slaves:\n  - { product_code: 0x07D83052, revision: 0x00120000, pdo_mapping: Standard }\n"), ElementsAre("net-pdo-mapping"));
    EXPECT_THAT(build_errors("slaves:\n  - { product_code: 0x04E43052, revision: 0x00120000, pdo_mapping: Standard (MDP 125) }\n"),
                ElementsAre());
    EXPECT_THAT(build_errors("slaves:\n  - { product_code: 0x04E43052, revision: 0x00120000, pdo_mapping: Standrad (MDP 125) }\n", &text),
                ElementsAre("net-pdo-mapping"));
    EXPECT_NE(text.find("did you mean 'Standard (MDP 125)'?"), std::string::npos) << text;
}

TEST(NetworkBuild, ConfiguredEntriesAreCheckedAgainstTheDictionary) {
    ESI_REQUIRE_CORPUS();
    std::string text;
    const std::string head = std::string("slaves:\n  - ") + "{ " + elmo + ", pdos: [0x1607, 0x1A00], pdo_entries: { 0x1607: [";
    EXPECT_THAT(build_errors(head + "0x6040:0:32] } }\n", &text), ElementsAre("net-entry-size"));
    EXPECT_NE(text.find("0x6040:00 (Controlword) is 16 bits, not 32"), std::string::npos) << text;
    EXPECT_THAT(build_errors(head + "0x60C5:0:32] } }\n", &text), ElementsAre("net-entry-not-mappable"));
    EXPECT_THAT(build_errors(head + "0x6041:0:16] } }\n", &text), ElementsAre("net-entry-not-mappable"));  // a TxPDO object
    EXPECT_THAT(build_errors(head + "0x7777:0:16] } }\n", &text), ElementsAre("net-entry-unknown"));
    EXPECT_THAT(build_errors(head + "0x60FE:9:32] } }\n", &text), ElementsAre("net-entry-unknown"));
    EXPECT_NE(text.find("has no sub-index 09; it has 00, 01, 02"), std::string::npos) << text;
    EXPECT_THAT(build_errors(head + "0x6040:0:16, 0x0:0:16, 0x6060:0:8] } }\n"), ElementsAre());
    // Fixed PDOs, PDOs not assigned, devices without PdoConfig.
    EXPECT_THAT(build_errors(std::string("slaves:\n  - { ") + elmo + ", pdos: [0x1601, 0x1A00], pdo_entries: { 0x1601: [0x6040:0:16] } }\n"),
                ElementsAre("net-pdo-fixed"));
    EXPECT_THAT(build_errors(std::string("slaves:\n  - { ") + elmo + ", pdo_entries: { 0x1607: [0x6040:0:16] } }\n"), ElementsAre("net-pdo-entries"));
    EXPECT_THAT(build_errors("slaves:\n  - { device: ECAT_CIA402, pdo_entries: { 0x1602: [0x6040:0:16] } }\n"), ElementsAre("net-pdo-fixed"));
    // Limits: entries per PDO and bit lengths.
    EXPECT_THAT(build_errors(head + "0x6040:0:16, 0x6060:0:8] }, limits: { max_entries_per_pdo: 1, bitlen: [16, 32] } }\n"),
                ElementsAre("net-limit-entries", "net-limit-bitlen"));
}

TEST(NetworkBuild, StartUpSdosAreCheckedAndEncoded) {
    ESI_REQUIRE_CORPUS();
    std::string text;
    const std::string head = std::string("slaves:\n  - { ") + elmo + ", sdos: [";
    EXPECT_THAT(build_errors(head + "{ index: 0x6041, value: 1 }] }\n", &text), ElementsAre("net-sdo-read-only"));
    EXPECT_THAT(build_errors(head + "{ index: 0x6060, value: 300 }] }\n", &text), ElementsAre("net-sdo-value"));
    EXPECT_NE(text.find("0x6060:00:"), std::string::npos) << text;
    EXPECT_THAT(build_errors(head + "{ index: 0x3FFF, value: 1 }] }\n", &text), ElementsAre("net-sdo-object", "net-sdo-type"));
    EXPECT_THAT(build_errors(head + "{ index: 0x3FFF, type: UINT, value: 70000 }] }\n"), ElementsAre("net-sdo-value"));
    EXPECT_THAT(build_errors(head + "{ index: 0x6060, value: 8, complete_access: true }] }\n"), ElementsAre("net-sdo-complete-access"));
    EXPECT_THAT(build_errors(head + "{ index: 0x6060, value: 8, transition: IB }] }\n"), ElementsAre("net-transition"));
    // BOOT's mailbox carries no CoE, and a "stay" transition the ENI allows runs no mailbox either.
    EXPECT_THAT(build_errors(head + "{ index: 0x6060, value: 8, transition: BI }] }\n"), ElementsAre("net-transition"));
    EXPECT_THAT(build_errors(head + "{ index: 0x6060, value: 8, transition: PP }] }\n", &text), ElementsAre("net-transition"));
    EXPECT_NE(text.find("an SDO cannot be sent at PP"), std::string::npos) << text;
    // Not a transition at all: refused when the file is read, with the nearest name.
    EXPECT_THAT(read_errors("slaves:\n  - { device: X, sdos: [{ index: 0x6060, value: 8, transition: PX }] }\n", &text),
                ElementsAre("net-transition"));
    EXPECT_NE(text.find("'PX' is not a state transition"), std::string::npos) << text;
    EXPECT_THAT(build_errors(head + "{ index: 0x6060, value: 8, transition: SO }], limits: { transitions: [PS] } }\n"),
                ElementsAre("net-limit-transition"));
    EXPECT_THAT(build_errors(head + "{ index: 0x607A, value: 1 }], limits: { max_init_cmd_bytes: 2 } }\n"), ElementsAre("net-limit-sdo-size"));
    EXPECT_THAT(build_errors("slaves:\n  - { product_code: 0x07D83052, revision: 0x00120000, sdos: [{ index: 0x8000, data: '01' }] }\n"),
                ElementsAre("net-sdo-no-coe"));

    const esi::net::BuildResult ok = esi::test::build_corpus_network(
        head + "{ index: 0x607A, value: -2 }, { index: 0x3FFF, type: STRING(4), value: ab }, { index: 0x6060, data: '0a', transition: [PS, SO] }] }\n");
    ASSERT_TRUE(ok.network) << esi::test::diagnostics_text(ok.diagnostics);
    const auto& cmds = ok.network->slaves[0].coe_init_cmds;
    ASSERT_GE(cmds.size(), 3u);
    const auto& a = cmds[cmds.size() - 3];
    const auto& b = cmds[cmds.size() - 2];
    const auto& c = cmds[cmds.size() - 1];
    EXPECT_EQ(a.data, (std::vector<std::uint8_t>{0xFE, 0xFF, 0xFF, 0xFF}));
    EXPECT_EQ(b.data, (std::vector<std::uint8_t>{'a', 'b'}));
    EXPECT_EQ(c.data, (std::vector<std::uint8_t>{0x0A}));
    EXPECT_EQ(c.transitions, (std::vector<std::string>{"PS", "SO"}));
    EXPECT_EQ(ok.diagnostics.count(esi::Severity::warning), 1u);  // 0x3FFF is not in the dictionary
}

TEST(NetworkBuild, AnImageLargerThanAFrameIsSplitAcrossFrames) {
    // 120 sample servos, 13 bytes each: more than the 1,486 data bytes of one frame.
    std::string yaml = "esi: [" + (esi::test::source_dir() / "samples" / "servo-item-c-series.yaml").string() + "]\nslaves:\n";
    for (int i = 0; i < 120; ++i) yaml += "  - { device: Metronix ECAT, pdos: [0x1600, 0x1601, 0x1602, 0x1603, 0x1A00, 0x1A01, 0x1A02, 0x1A03] }\n";
    const esi::net::NetworkFileResult read = esi::net::read_network_text(yaml, "n.yaml");
    ASSERT_TRUE(read.spec);
    const esi::net::BuildResult built = esi::net::build_network(*read.spec, esi::net::BuildOptions{});
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    const esi::net::Network& n = *built.network;
    ASSERT_EQ(n.image.frames.size(), 2u);
    std::uint32_t expected_logical = n.image.logical_base;
    std::size_t slaves_seen = 0;
    for (const esi::net::Frame& f : n.image.frames) {
        std::uint32_t frame_bytes = 0;
        for (const esi::net::Datagram& d : f.datagrams) frame_bytes += 10 + d.length + 2;
        EXPECT_LE(frame_bytes, 1498u);
        const auto lrw = std::find_if(f.datagrams.begin(), f.datagrams.end(),
                                      [](const esi::net::Datagram& d) { return d.command == esi::net::Datagram::Command::lrw; });
        ASSERT_NE(lrw, f.datagrams.end());
        EXPECT_EQ(lrw->logical, expected_logical);  // the frames cover the image without a gap
        expected_logical += lrw->length;
        const std::size_t in_frame = lrw->length / 13;
        EXPECT_EQ(lrw->length % 13, 0u);  // no slave straddles two frames
        EXPECT_EQ(lrw->working_counter, 3 * in_frame);
        slaves_seen += in_frame;
    }
    EXPECT_EQ(slaves_seen, 120u);
    EXPECT_EQ(n.image.process_data_bytes, 120u * 13);
    // Each slave's data lie in the LRW of its frame.
    for (const esi::net::NetworkSlave& s : n.slaves) {
        const auto& datagrams = n.image.frames[s.frame].datagrams;
        const auto lrw = std::find_if(datagrams.begin(), datagrams.end(),
                                      [](const esi::net::Datagram& d) { return d.command == esi::net::Datagram::Command::lrw; });
        EXPECT_GE(n.image.logical_base + s.image_offset, lrw->logical);
        EXPECT_LE(n.image.logical_base + s.image_offset + 13, lrw->logical + lrw->length);
    }
}

TEST(EsiNetCli, NothingIsWrittenOnErrorAndTheExitCodesTellTheKind) {
    ESI_REQUIRE_CORPUS();
    esi::test::TempDir dir;
    const std::string tool = esi::test::tool("esi-net").string();
    esi::test::write_text(dir / "out" / "network.xml", "previous");
    // A network error: exit 1, the previous output stays.
    esi::test::write_text(dir / "bad.yaml", "esi: [" + esi::test::corpus_esi_dir().string() + "]\nslaves:\n  - { product_code: 0x07D83052, pdos: [0x1777] }\n");
    auto r = esi::test::run({tool, "--no-cache", "build", (dir / "bad.yaml").string(), "-o", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("bad.yaml:3:40: error: EL2008 has no RxPDO 0x1777"), std::string::npos) << r.err;
    EXPECT_EQ(esi::test::read_text(dir / "out" / "network.xml"), "previous");
    EXPECT_FALSE(fs::exists(dir / "out" / "lcec.xml"));
    // An invalid network file: exit 2.
    esi::test::write_text(dir / "invalid.yaml", "slaves:\n  - { devise: EL2008 }\n");
    r = esi::test::run({tool, "build", (dir / "invalid.yaml").string(), "-o", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("did you mean 'device'?"), std::string::npos) << r.err;
    // Unreadable files and usage errors: exit 2.
    EXPECT_EQ(esi::test::run({tool, "build", (dir / "missing.yaml").string(), "-o", (dir / "out").string()}).exit_code, 2);
    EXPECT_EQ(esi::test::run({tool, "build", (dir / "bad.yaml").string(), "-o", (dir / "out").string(), "--only", "eni,pdf"}).exit_code, 2);
    EXPECT_EQ(esi::test::run({tool, "build", (dir / "bad.yaml").string()}).exit_code, 2);
    EXPECT_EQ(esi::test::run({tool, "init", "--from-igh", (dir / "bad.yaml").string(), "-o", (dir / "n.yaml").string()}).exit_code, 2);
    EXPECT_FALSE(fs::exists(dir / "n.yaml"));
    // No ESI path at all.
    esi::test::write_text(dir / "no-esi.yaml", "slaves:\n  - { device: EL2008 }\n");
    r = esi::test::run({tool, "--no-cache", "build", (dir / "no-esi.yaml").string(), "-o", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("[net-no-esi]"), std::string::npos) << r.err;
    const auto version = esi::test::run({tool, "--version"});
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_EQ(version.out.rfind("esi-net (libesi) ", 0), 0u);
}

}  // namespace
