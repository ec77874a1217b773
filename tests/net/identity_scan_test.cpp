// The identity scan (esi/xml/identity_scan.hpp) against the full reader: for every corpus file
// the reader accepts, the scan lists the same devices in the same order with the same identity,
// Type text and vendor id; and the markup it must step over (comments, CDATA, entities).

#include <gtest/gtest.h>

#include "esi/device_selector.hpp"
#include "esi/io/read_file.hpp"
#include "esi/xml/identity_scan.hpp"
#include "esi/xml/reader.hpp"
#include "support/test_support.hpp"

namespace {

TEST(IdentityScan, MatchesTheReaderOnEveryCorpusFile) {
    ESI_REQUIRE_CORPUS();
    std::size_t files = 0, devices = 0;
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (entry.path().extension() != ".xml") continue;
        const esi::ReadResult read = esi::read_esi_file(entry.path());
        std::string error;
        const auto bytes = esi::read_file_bytes(entry.path(), error);
        ASSERT_TRUE(bytes) << error;
        const esi::IdentityScan scan = esi::scan_identities(*bytes);
        if (!read.document) continue;  // not well-formed: the index falls back to the reader's error
        ++files;
        ASSERT_TRUE(scan.ok()) << entry.path() << ": " << scan.error;
        const std::vector<const esi::Device*> model = esi::select_devices(*read.document, std::nullopt);
        ASSERT_EQ(scan.devices.size(), model.size()) << entry.path();
        for (std::size_t i = 0; i < model.size(); ++i) {
            const esi::ScannedDevice& s = scan.devices[i];
            const esi::Device& d = *model[i];
            const esi::EtherCATInfo* info = read.document->info_of(d);
            EXPECT_EQ(s.ordinal, i);
            EXPECT_EQ(s.product_code, d.type.product_code) << entry.path() << " #" << i;
            EXPECT_EQ(s.revision_no, d.type.revision_no) << entry.path() << " #" << i;
            EXPECT_EQ(s.type, d.type.text) << entry.path() << " #" << i;
            EXPECT_EQ(s.name, esi::primary_text(d.names)) << entry.path() << " #" << i;
            EXPECT_EQ(s.vendor_id, info && info->vendor ? info->vendor->id : std::nullopt) << entry.path() << " #" << i;
            EXPECT_EQ(s.vendor_name, info && info->vendor ? std::string(esi::trim(esi::primary_text(info->vendor->names))) : std::string())
                << entry.path() << " #" << i;
            EXPECT_EQ(s.pos.line, d.pos.line) << entry.path() << " #" << i;
            ++devices;
        }
    }
    EXPECT_GT(files, 80u);
    EXPECT_GT(devices, 900u);
}

TEST(IdentityScan, StepsOverCommentsCdataAndEntities) {
    const std::string xml = R"(<?xml version="1.0"?>
<!-- <Device><Type ProductCode="#x9">commented out</Type></Device> -->
<EtherCATInfo><Vendor><Id>#x2</Id></Vendor><Descriptions><Devices>
  <Device Physics="YY"><Type ProductCode="#x10" RevisionNo="2">A &amp; B</Type>
    <Name LcId="1031"><![CDATA[Deutsch <x>]]></Name><Name LcId="1033">English</Name>
    <Info><![CDATA[</Device>]]></Info><Sm>x</Sm></Device>
  <Device><Type ProductCode="17">C</Type><Name>Only</Name></Device>
</Devices></Descriptions></EtherCATInfo>)";
    const esi::IdentityScan scan = esi::scan_identities(xml);
    ASSERT_TRUE(scan.ok()) << scan.error;
    ASSERT_EQ(scan.devices.size(), 2u);
    EXPECT_EQ(scan.devices[0].type, "A & B");
    EXPECT_EQ(scan.devices[0].name, "English");
    EXPECT_EQ(scan.devices[0].product_code, 0x10u);
    EXPECT_EQ(scan.devices[0].revision_no, 2u);
    EXPECT_EQ(scan.devices[0].vendor_id, 2u);
    EXPECT_EQ(scan.devices[0].pos.line, 4u);
    EXPECT_EQ(scan.devices[1].product_code, 17u);
    EXPECT_EQ(scan.devices[1].name, "Only");
}

TEST(IdentityScan, ReportsMarkupItCannotTokenise) {
    EXPECT_FALSE(esi::scan_identities("<EtherCATInfo><Descriptions><!-- never closed").ok());
    EXPECT_FALSE(esi::scan_identities("<EtherCATInfo><Vendor></EtherCATInfo>").ok());
}

}  // namespace
