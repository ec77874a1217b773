// `init --from-eni` on every real export in ../shared/corpus/eni/: ENI -> NETWORK.yaml -> build
// -> ENI, compared slave by slave with the export on the aspects tests/net/eni_corpus_test.cpp
// compares (identity, ProcessData, CoE InitCmds, register InitCmds, DC, process-image
// variables). Exceptions, each for a reason of data (docs/esi-net.md, "init --from-eni"):
//  - slaves whose identity no corpus ESI describes are written as comments (--omit-unknown):
//    mega_master's EL4002 and its EL1809 at revision 0x00120000 (the corpus has 0x00100000 only),
//    test_eni's IMU;
//  - EC-Engineer's 5000 ms PREOP timeout on SP/OP, as in the corpus comparison;
//  - the encrypted Murrelektronik export is refused.

#include <gtest/gtest.h>

#include <algorithm>

#include "esi/net/eni_import.hpp"
#include "esi/net/network_spec.hpp"
#include "esi/net/outputs.hpp"
#include "net/eni_slaves.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::EniSlave;

std::vector<std::string> facts(const EniSlave& s) {
    std::vector<std::string> out;
    out.push_back("identity " + std::to_string(s.vendor_id) + " " + std::to_string(s.product_code) + " " + std::to_string(s.revision));
    out.push_back("send " + (s.send_bits ? std::to_string(*s.send_bits) : std::string("-")) + " recv " +
                  (s.recv_bits ? std::to_string(*s.recv_bits) : std::string("-")));
    for (const auto& sm : s.sms) {
        std::string line = "sm" + std::to_string(sm.number) + " " + sm.type + " " + std::to_string(sm.start) + " " + std::to_string(sm.control) +
                           (sm.enable ? " on" : " off");
        for (std::uint32_t p : sm.pdos) line += " " + std::to_string(p);
        out.push_back(line);
    }
    for (const auto& p : s.pdos) {
        std::string line = "pdo " + p.direction + " " + std::to_string(p.index) + " sm " + std::to_string(p.sm);
        for (const std::string& e : p.entries) line += " " + e;
        out.push_back(line);
    }
    for (const std::string& c : s.coe_init_cmds) out.push_back("coe " + c);
    for (const std::string& r : s.register_cmds) out.push_back("reg " + r);
    out.push_back("dc " + s.dc.value_or("none"));
    for (const std::string& v : s.outputs) out.push_back("out " + v);
    for (const std::string& v : s.inputs) out.push_back("in " + v);
    return out;
}

struct Exception {
    std::string ours, theirs;
};

std::string join(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += "\n    " + l;
    return out;
}

// Imports `file`, builds the network and compares every written slave with the export's.
void round_trip(const std::string& file, std::size_t expected_slaves, const std::vector<Exception>& exceptions = {},
                const esi::net::LibraryIndex* library = nullptr) {
    SCOPED_TRACE(file);
    const std::string text = esi::test::read_text(esi::test::corpus_dir() / "eni" / file);
    esi::net::EniImportOptions options;
    options.omit_unknown = true;
    const esi::net::EniImport imported =
        esi::net::network_from_eni(text, file, library ? *library : esi::test::corpus_index(), options);
    ASSERT_FALSE(imported.yaml.empty()) << esi::test::diagnostics_text(imported.diagnostics);
    EXPECT_EQ(imported.written.size(), expected_slaves) << imported.yaml;
    const esi::net::NetworkFileResult read = esi::net::read_network_text(imported.yaml, "imported.yaml");
    ASSERT_TRUE(read.spec) << esi::test::diagnostics_text(read.diagnostics) << imported.yaml;
    const esi::net::BuildResult built = esi::net::build_network(*read.spec, library ? *library : esi::test::corpus_index());
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics) << imported.yaml;
    const esi::test::EniFile ours = esi::test::read_eni(esi::net::write_eni(*built.network));
    const esi::test::EniFile theirs = esi::test::read_eni(text);
    ASSERT_EQ(ours.slaves.size(), imported.written.size());
    for (std::size_t k = 0; k < ours.slaves.size(); ++k) {
        std::vector<std::string> a = facts(ours.slaves[k]);
        const std::vector<std::string> b = facts(theirs.slaves[imported.written[k]]);
        for (const Exception& e : exceptions)
            for (std::string& line : a)
                if (line == e.ours) line = e.theirs;
        EXPECT_EQ(a, b) << "slave " << k << " (export slave " << imported.written[k] << ")\n  ours:" << join(a) << "\n  export:" << join(b)
                        << "\n" << imported.yaml;
    }
}

TEST(EniImport, TwinCatMegaMaster) {
    ESI_REQUIRE_CORPUS();
    round_trip("jasper-node__jn-ec-master__mega_master_eni.xml", 2);
}

TEST(EniImport, TwinCatElmoDrivesWithDc) {
    ESI_REQUIRE_CORPUS();
    round_trip("kpierczy__ethercat-lib__test_eni.xml", 4);
}

TEST(EniImport, EcEngineerElmoDrives) {
    ESI_REQUIRE_CORPUS();
    round_trip("magnate3__rocos-ethercat__eni4.xml", 4,
               {{"reg SP,OP|set device state to PREOP|cycle|cmd 5|adp phys|ado 288|1200|cnt |retries 300|timeout 200",
                 "reg SP,OP|set device state to PREOP|cycle|cmd 5|adp phys|ado 288|1200|cnt |retries 300|timeout 5000"}});
}

TEST(EniImport, TwinCatCherryEcatModularDrive) {
    ESI_REQUIRE_CORPUS();
    const std::string file = "cherry-embedded__CherryECAT__ECAT_CIA402_ENI.xml";
    // The corpus holds several files for this drive's identity that configure it differently:
    // against the whole library the import refuses to choose for the user ...
    const std::string text = esi::test::read_text(esi::test::corpus_dir() / "eni" / file);
    esi::net::EniImportOptions options;
    options.omit_unknown = true;
    const esi::net::EniImport refused = esi::net::network_from_eni(text, file, esi::test::corpus_index(), options);
    EXPECT_TRUE(refused.yaml.empty());
    EXPECT_NE(esi::test::diagnostics_text(refused.diagnostics).find("net-device-duplicate"), std::string::npos)
        << esi::test::diagnostics_text(refused.diagnostics);
    // ... and with the library narrowed to the file the user means (--esi FILE) it round-trips.
    const esi::net::IndexOptions index_options;  // no cache_dir: no cache
    const esi::net::IndexResult narrowed =
        esi::net::build_library_index({esi::test::corpus_dir() / "esi" / "HPMicro__ECAT_CIA402__hpm_sdk__2024-09.xml"}, index_options);
    ASSERT_FALSE(narrowed.diagnostics.has_errors()) << esi::test::diagnostics_text(narrowed.diagnostics);
    round_trip(file, 1, {}, &narrowed.index);
}

TEST(EniImport, TwinCatEmptyNetwork) {
    ESI_REQUIRE_CORPUS();
    const std::string text = esi::test::read_text(esi::test::corpus_dir() / "eni" / "kj4tmp__pyecm__empty.xml");
    const esi::net::EniImport imported = esi::net::network_from_eni(text, "empty.xml", esi::test::corpus_index(), {});
    EXPECT_NE(imported.yaml.find("slaves: []"), std::string::npos) << imported.yaml << esi::test::diagnostics_text(imported.diagnostics);
}

TEST(EniImport, EncryptedEniIsRefused) {
    ESI_REQUIRE_CORPUS();
    const std::string text = esi::test::read_text(esi::test::corpus_dir() / "eni" / "Murrelektronik__VarioX-IPC-DemoCase__eni.xml");
    const esi::net::EniImport imported = esi::net::network_from_eni(text, "eni.xml", esi::test::corpus_index(), {});
    EXPECT_TRUE(imported.yaml.empty());
    EXPECT_NE(esi::test::diagnostics_text(imported.diagnostics).find("[net-eni-encrypted]"), std::string::npos)
        << esi::test::diagnostics_text(imported.diagnostics);
}

TEST(EniImport, UnknownSlavesKeepTheirPlaceByDefault) {
    ESI_REQUIRE_CORPUS();
    const std::string text = esi::test::read_text(esi::test::corpus_dir() / "eni" / "kpierczy__ethercat-lib__test_eni.xml");
    const esi::net::EniImport imported = esi::net::network_from_eni(text, "test_eni.xml", esi::test::corpus_index(), {});
    ASSERT_FALSE(imported.yaml.empty()) << esi::test::diagnostics_text(imported.diagnostics);
    EXPECT_EQ(imported.written.size(), 5u);
    EXPECT_NE(esi::test::diagnostics_text(imported.diagnostics).find("[net-eni-unknown]"), std::string::npos);
}

TEST(EniImport, NotAnEniIsAnError) {
    const esi::net::LibraryIndex empty;
    for (const char* text : {"<EtherCATInfo/>", "<EtherCATConfig><Config>", "not xml"}) {
        const esi::net::EniImport imported = esi::net::network_from_eni(text, "x.xml", empty, {});
        EXPECT_TRUE(imported.yaml.empty()) << text;
        EXPECT_TRUE(imported.diagnostics.has_errors()) << text;
    }
}

// An ENI esi-net wrote comes back as the network it was written from (same per-slave content).
TEST(EniImport, EsiNetsOwnEniRoundTrips) {
    ESI_REQUIRE_CORPUS();
    for (const esi::test::NamedNetwork& n : esi::test::corpus_networks()) {
        SCOPED_TRACE(n.name);
        // An ENI does not name the modules in a modular device's slots; init does not recover them.
        if (n.yaml.find("modules:") != std::string::npos) continue;
        const esi::net::BuildResult first = esi::test::build_corpus_network(n.yaml);
        ASSERT_TRUE(first.network) << esi::test::diagnostics_text(first.diagnostics);
        const std::string eni = esi::net::write_eni(*first.network);
        const esi::net::EniImport imported = esi::net::network_from_eni(eni, n.name + ".xml", esi::test::corpus_index(), {});
        ASSERT_FALSE(imported.yaml.empty()) << esi::test::diagnostics_text(imported.diagnostics);
        const esi::net::BuildResult second = esi::test::build_corpus_network(imported.yaml);
        ASSERT_TRUE(second.network) << esi::test::diagnostics_text(second.diagnostics) << imported.yaml;
        EXPECT_EQ(esi::net::write_eni(*second.network), eni) << imported.yaml;
    }
}

}  // namespace

namespace {

// Names, comments and transitions come from the ENI: written as quoted YAML text, they come back
// as the same text, and a transition that is none is refused rather than written into the file.
TEST(EniImport, TextFromTheEniStaysText) {
    ESI_REQUIRE_CORPUS();
    const esi::test::NamedNetwork& n = esi::test::corpus_networks()[2];  // elmo-configured: named start-up SDOs
    ASSERT_EQ(n.name, "elmo-configured");
    const esi::net::BuildResult first = esi::test::build_corpus_network(n.yaml);
    ASSERT_TRUE(first.network) << esi::test::diagnostics_text(first.diagnostics);
    std::string eni = esi::net::write_eni(*first.network);
    const std::string hostile = "Axis \"1\"\n# x: [y] {z} ${w}";
    const std::size_t at = eni.find("<![CDATA[Axis 1]]>");
    ASSERT_NE(at, std::string::npos);
    eni.replace(at, 18, "<![CDATA[" + hostile + "]]>");
    const esi::net::EniImport imported = esi::net::network_from_eni(eni, "hostile.xml", esi::test::corpus_index(), {});
    ASSERT_FALSE(imported.yaml.empty()) << esi::test::diagnostics_text(imported.diagnostics);
    const esi::net::NetworkFileResult read = esi::net::read_network_text(imported.yaml, "imported.yaml");
    ASSERT_TRUE(read.spec) << imported.yaml;
    EXPECT_EQ(read.spec->slaves[0].name, hostile);

    std::string bad = esi::net::write_eni(*first.network);
    // The network's SDO 0x6065 is sent on PS and SO: its CoE InitCmd's SO transition.
    const std::size_t sdo = bad.rfind("<Transition>SO</Transition>", bad.find("<![CDATA[0x6065:00]]>"));
    ASSERT_NE(sdo, std::string::npos);
    bad.replace(sdo, 27, "<Transition>SO], evil: [1</Transition>");
    const esi::net::EniImport refused = esi::net::network_from_eni(bad, "bad.xml", esi::test::corpus_index(), {});
    EXPECT_TRUE(refused.yaml.empty());
    EXPECT_NE(esi::test::diagnostics_text(refused.diagnostics).find("[net-transition]"), std::string::npos)
        << esi::test::diagnostics_text(refused.diagnostics);
}

}  // namespace

namespace {

// An ENI that maps an entry the ESI marks not mappable (as EC-Engineer maps an Elmo drive's
// 0x60FE:00) comes back with the entry under force_entries, and builds the same ENI again.
TEST(EniImport, EntriesTheEsiDoesNotMapAreForced) {
    ESI_REQUIRE_CORPUS();
    const std::string yaml = "master: { name: Line, cycle_time_us: 1000 }\nslaves:\n  - name: Axis\n    product_code: 0x00030924\n"
                             "    revision: 0x00010420\n    pdos: [0x1607, 0x1A07]\n"
                             "    pdo_entries: { 0x1607: [0x607A:0:32, 0x60FE:0x00:8], 0x1A07: [0x6064:0:32] }\n"
                             "    force_entries: [0x60FE:0x00]\n";
    const esi::net::BuildResult first = esi::test::build_corpus_network(yaml);
    ASSERT_TRUE(first.network) << esi::test::diagnostics_text(first.diagnostics);
    const std::string eni = esi::net::write_eni(*first.network);
    const esi::net::EniImport imported = esi::net::network_from_eni(eni, "forced.xml", esi::test::corpus_index(), {});
    ASSERT_FALSE(imported.yaml.empty()) << esi::test::diagnostics_text(imported.diagnostics);
    EXPECT_NE(imported.yaml.find("force_entries: [0x60FE:0x00]"), std::string::npos) << imported.yaml;
    EXPECT_NE(esi::test::diagnostics_text(imported.diagnostics).find("[net-eni-forced]"), std::string::npos);
    const esi::net::BuildResult second = esi::test::build_corpus_network(imported.yaml);
    ASSERT_TRUE(second.network) << esi::test::diagnostics_text(second.diagnostics);
    EXPECT_EQ(esi::net::write_eni(*second.network), eni);
}

}  // namespace
