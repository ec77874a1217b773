// Text from outside (a scanned device name, an ESI Type text, a path) reaches NETWORK.yaml only
// as a quoted scalar, whatever characters it holds, and the YAML writer and reader agree on
// what a line break is (issue 27, item 1).

#include <gtest/gtest.h>

#include "esi/net/igh_scan.hpp"
#include "esi/net/network_spec.hpp"
#include "import/yaml_emitter.hpp"
#include "net/net_test_support.hpp"

namespace {

// Every character the YAML reader (libyaml) takes for a line break, and others that must not
// pass a writer raw: NEL, LINE and PARAGRAPH SEPARATOR, CR, LF, NUL, ESC, a BOM, U+FFFE.
const std::vector<std::string> hostile_texts = {
    "a\u2028b",          "a\u2029b",          "a\xC2\x85" "b",      "a\rb",  "a\nb", std::string("a\0b", 3), "a\x1b[31mb",
    "\xEF\xBB\xBF" "a",     "a\xEF\xBF\xBE",     "\"quoted\" 'single'", "a: b",  "# c",   "- d",                  "x\\y",
    "  leading blank ",  "trailing\u2028",    "\u2028",             "\t",    "?",     "{ a: 1 }",             "*alias &anchor !tag",
};

TEST(HostileNames, TheYamlWriterAndReaderAgreeOnEveryText) {
    for (const std::string& text : hostile_texts) {
        const std::string yaml = "master: { name: " + esi::import_detail::quote_text(text) + " }\nslaves: []\n";
        const esi::net::NetworkFileResult r = esi::net::read_network_text(yaml, "n.yaml");
        ASSERT_TRUE(r.spec) << yaml << esi::test::diagnostics_text(r.diagnostics);
        EXPECT_EQ(r.spec->master.name, text) << yaml;
    }
}

esi::net::IghScan scan_named(const std::string& device_name) {
    const std::string text = "=== Master 0, Slave 0 ===\nDevice name: " + device_name +
                             "\nIdentity:\n  Vendor Id:       0x00000002\n  Product code:    0x03f03052\n  Revision number: 0x00100000\n";
    esi::net::IghScan scan = esi::net::parse_igh_slaves(text, "scan.txt");
    EXPECT_FALSE(scan.diagnostics.has_errors()) << esi::test::diagnostics_text(scan.diagnostics);
    return scan;
}

// The network init writes, read back: one slave with exactly the scanned identity.
void expect_only_the_scanned_slave(const std::string& yaml) {
    const esi::net::NetworkFileResult r = esi::net::read_network_text(yaml, "n.yaml");
    ASSERT_TRUE(r.spec) << yaml << esi::test::diagnostics_text(r.diagnostics);
    ASSERT_EQ(r.spec->slaves.size(), 1u) << yaml;
    const esi::net::SlaveSpec& s = r.spec->slaves[0];
    EXPECT_EQ(s.name, "D1") << yaml;
    EXPECT_FALSE(s.alias) << yaml;
    EXPECT_TRUE(s.sdos.empty()) << yaml;
    EXPECT_EQ(s.product_code, 0x03f03052u) << yaml;
}

TEST(HostileNames, AScannedDeviceNameCannotAddKeys) {
    for (const std::string brk : {"\u2028", "\u2029", "\xC2\x85", "\r", "\n"}) {
        const std::string name = "EL1008" + brk + "    alias: 7" + brk + "    sdos: [{ index: 0x1C12, value: 0 }]";
        const esi::net::InitResult init = esi::net::network_from_scan(scan_named(name), nullptr, {});
        expect_only_the_scanned_slave(init.yaml);
    }
}

TEST(HostileNames, AnEsiTypeTextCannotAddKeys) {
    esi::net::LibraryIndex index;
    esi::net::IndexedFile file;
    file.path = "lib/evil.xml";
    index.files.push_back(file);
    esi::net::IndexedDevice d;
    d.vendor_id = 2;
    d.product_code = 0x03f03052;
    d.revision_no = 0x00100000;
    d.type = "EL1008\u2028    alias: 9\u2029    sdos: [{ index: 0x1C12, value: 0 }]";
    index.devices.push_back(d);
    const esi::net::InitResult init = esi::net::network_from_scan(scan_named("EL1008"), &index, {});
    expect_only_the_scanned_slave(init.yaml);
}

TEST(HostileNames, EsiPathsAreWrittenAsTheyAreRead) {
    esi::net::InitOptions options;
    options.esi = {"lib\ndir", "a\u2028b", "quote\"back\\slash"};
    const esi::net::InitResult init = esi::net::network_from_scan(scan_named("EL1008"), nullptr, options);
    const esi::net::NetworkFileResult r = esi::net::read_network_text(init.yaml, "n.yaml");
    ASSERT_TRUE(r.spec) << init.yaml << esi::test::diagnostics_text(r.diagnostics);
    EXPECT_EQ(r.spec->esi, options.esi) << init.yaml;
}

}  // namespace
