// The builder: where every ESI value lands, and every limit reported as a diagnostic (never a
// silent truncation).

#include <gtest/gtest.h>

#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "esi/sii/mapping.hpp"
#include "fixture.hpp"

namespace {

using namespace esi::sii;
using esi::Severity;
using esi::test::build_fixture;
using esi::test::fixture_xml;
using esi::test::has_rule;

TEST(SiiBuild, HeaderWordsComeFromIdentityEepromAndMailbox) {
    const BuildResult r = build_fixture(fixture_xml());
    ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    const DecodedImage d = decode_image(r.bytes);
    EXPECT_TRUE(d.faults.empty()) << d.faults.front().message;
    const Header& h = d.image.header;
    EXPECT_EQ(h.config_word(0), 0x050E);
    EXPECT_EQ(h.config_word(1), 0x0603);
    EXPECT_EQ(h.config_word(2), 0x2710);
    EXPECT_EQ(h.config_word(3), 0x0000);
    EXPECT_EQ(h.checksum, config_crc(h.config_data));
    EXPECT_EQ(h.vendor_id, 0xABCDu);
    EXPECT_EQ(h.product_code, 0x1234u);
    EXPECT_EQ(h.revision_no, 0x00020001u);
    EXPECT_EQ(h.bootstrap_receive_offset, 0x1000);
    EXPECT_EQ(h.bootstrap_receive_size, 0x0200);
    EXPECT_EQ(h.bootstrap_send_offset, 0x1200);
    EXPECT_EQ(h.bootstrap_send_size, 0x0200);
    EXPECT_EQ(h.standard_receive_offset, 0x1000);
    EXPECT_EQ(h.standard_receive_size, 128);
    EXPECT_EQ(h.standard_send_offset, 0x1080);
    EXPECT_EQ(h.standard_send_size, 128);
    EXPECT_EQ(h.mailbox_protocols, mailbox_protocol::coe | mailbox_protocol::foe | mailbox_protocol::eoe);
    EXPECT_EQ(h.size, 15);  // 2048 bytes
    EXPECT_EQ(h.version, 1);
    EXPECT_EQ(r.bytes.size(), 2048u);
    EXPECT_EQ(r.bytes.back(), 0xFF);  // erased-EEPROM padding
}

TEST(SiiBuild, GeneralCategoryCarriesNamesMailboxDetailsCurrentAndPorts) {
    const BuildResult r = build_fixture(fixture_xml());
    const DecodedImage d = decode_image(r.bytes);
    const General* g = d.image.general();
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(d.image.string_at(g->group_idx), "TestGroup");
    EXPECT_EQ(d.image.string_at(g->order_idx), "TD-100");
    EXPECT_EQ(d.image.string_at(g->name_idx), "Test device 100");
    EXPECT_EQ(g->image_idx, 0);
    EXPECT_EQ(g->group_idx_duplicate, g->group_idx);
    EXPECT_EQ(g->coe_details, coe_detail::sdo | coe_detail::sdo_info | coe_detail::pdo_assign | coe_detail::complete_access);
    EXPECT_EQ(g->foe_details, 1);
    EXPECT_EQ(g->eoe_details, 1);
    EXPECT_EQ(g->flags, general_flag::mailbox_data_link_layer);
    EXPECT_EQ(g->current_on_ebus, -150);
    EXPECT_EQ(g->physical_ports, 0x0311);  // Y Y K
}

TEST(SiiBuild, NamesInTheRequestedLanguageAreIso88591) {
    BuildOptions german;
    german.name_lcid = 1031;
    const BuildResult r = build_fixture(fixture_xml(), german);
    const DecodedImage d = decode_image(r.bytes);
    EXPECT_EQ(d.image.string_at(d.image.general()->name_idx), std::string("Testger\xE4t 100"));
    // The µ of a PDO entry name is one byte too.
    bool found = false;
    for (const auto& s : d.image.strings()->items) found = found || s == std::string("Position \xB5m");
    EXPECT_TRUE(found);
}

TEST(SiiBuild, FmmuAndSyncManagerCategories) {
    const DecodedImage d = decode_image(build_fixture(fixture_xml()).bytes);
    EXPECT_EQ(d.image.fmmus()->usages, (std::vector<std::uint8_t>{1, 2, 3, 0xFF}));
    const auto& sms = d.image.sync_managers()->items;
    ASSERT_EQ(sms.size(), 4u);
    EXPECT_EQ(sms[0], (SyncManagerRecord{0x1000, 128, 0x26, 0, 0x01, 1}));
    EXPECT_EQ(sms[1], (SyncManagerRecord{0x1080, 128, 0x22, 0, 0x01, 2}));
    EXPECT_EQ(sms[2], (SyncManagerRecord{0x1100, 4, 0x64, 0, 0x09, 3}));  // OpOnly -> bit 3
    EXPECT_EQ(sms[3], (SyncManagerRecord{0x1180, 0, 0x20, 0, 0x05, 4}));  // Virtual -> bit 2
}

TEST(SiiBuild, PdoCategoriesWithOneByteDataTypes) {
    const DecodedImage d = decode_image(build_fixture(fixture_xml()).bytes);
    const Pdos* rx = d.image.pdos(category::rx_pdo);
    const Pdos* tx = d.image.pdos(category::tx_pdo);
    ASSERT_NE(rx, nullptr);
    ASSERT_NE(tx, nullptr);
    ASSERT_EQ(rx->items.size(), 1u);
    const PdoRecord& out = rx->items[0];
    EXPECT_EQ(out.index, 0x1600);
    EXPECT_EQ(out.sync_manager, 2);
    EXPECT_EQ(out.flags, pdo_flag::mandatory | pdo_flag::fixed_content);
    EXPECT_EQ(d.image.string_at(out.name_idx), "Outputs");
    ASSERT_EQ(out.entries.size(), 2u);
    EXPECT_EQ(out.entries[0], (PdoEntryRecord{0x7000, 1, out.entries[0].name_idx, 0x03, 16, 0}));  // INT
    EXPECT_EQ(out.entries[1], (PdoEntryRecord{0, 0, 0, 0, 16, 0}));                               // padding
    ASSERT_EQ(tx->items.size(), 2u);
    EXPECT_EQ(tx->items[0].entries[0].data_type, 0x04);  // DINT
    EXPECT_EQ(tx->items[0].entries[1].data_type, 0x09);  // STRING(1) -> VISIBLE_STRING
    EXPECT_EQ(tx->items[1].sync_manager, pdo_no_sync_manager);  // no @Sm
    EXPECT_TRUE(tx->items[1].entries.empty());
}

TEST(SiiBuild, DcCategorySkipsLegacyOpModes) {
    const BuildResult r = build_fixture(fixture_xml());
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-dc-legacy-op-mode", Severity::info));
    const DecodedImage d = decode_image(r.bytes);
    const DcOpModes* dc = d.image.dc();
    ASSERT_NE(dc, nullptr);
    ASSERT_EQ(dc->items.size(), 2u);
    const DcOpModeRecord& sync = dc->items[0];
    EXPECT_EQ(d.image.string_at(sync.name_idx), "DcSync");
    EXPECT_EQ(d.image.string_at(sync.desc_idx), "SYNC0");
    EXPECT_EQ(sync.assign_activate, 0x0300);
    EXPECT_EQ(sync.cycle_time0, 1000000u);
    EXPECT_EQ(static_cast<std::int32_t>(sync.shift_time0), -2500);
    EXPECT_EQ(sync.shift_time1, 7000u);
    EXPECT_EQ(sync.sync0_cycle_factor, 1);
    EXPECT_EQ(sync.sync1_cycle_factor, -2);
    EXPECT_EQ(d.image.string_at(dc->items[1].name_idx), "FreeRun");
}

TEST(SiiBuild, NoPdoAndNoDcLeaveTheirCategoriesOut) {
    BuildOptions options;
    options.include_pdos = false;
    options.include_dc = false;
    const DecodedImage d = decode_image(build_fixture(fixture_xml(), options).bytes);
    EXPECT_EQ(d.image.find(category::tx_pdo), nullptr);
    EXPECT_EQ(d.image.find(category::rx_pdo), nullptr);
    EXPECT_EQ(d.image.find(category::dc), nullptr);
    for (const auto& s : d.image.strings()->items) {
        EXPECT_NE(s, "Outputs");  // PDO names are not written either
        EXPECT_NE(s, "DcSync");
    }
}

TEST(SiiBuild, CategoriesComeInTheOrderOfTheRealImages) {
    const DecodedImage d = decode_image(build_fixture(fixture_xml("<Category><CatNo>1</CatNo><Data>D608</Data></Category>")).bytes);
    std::vector<std::uint16_t> types;
    for (const auto& c : d.image.categories) types.push_back(c.type);
    EXPECT_EQ(types, (std::vector<std::uint16_t>{1, 10, 30, 40, 41, 50, 51, 60}));
}

TEST(SiiBuild, EepromCategoriesAreCopiedVerbatim) {
    const BuildResult r = build_fixture(fixture_xml(
        "<Category><CatNo>1</CatNo><Data>D60806020602</Data></Category>"
        "<Category><CatNo>#x0800</CatNo><DataString>AKD</DataString></Category>"
        "<Category><CatNo>2049</CatNo><DataUINT>#x1234</DataUINT></Category>"
        "<Category><CatNo>2050</CatNo><DataUDINT>#x12345678</DataUDINT></Category>"));
    ASSERT_TRUE(r.ok());
    const DecodedImage d = decode_image(r.bytes);
    auto raw = [&](std::uint16_t type) { return std::get<RawData>(d.image.find(type)->content).bytes; };
    EXPECT_EQ(raw(1), (std::vector<std::uint8_t>{0xD6, 0x08, 0x06, 0x02, 0x06, 0x02}));
    EXPECT_EQ(raw(0x0800), (std::vector<std::uint8_t>{'A', 'K', 'D', 0}));
    EXPECT_EQ(raw(2049), (std::vector<std::uint8_t>{0x34, 0x12}));
    EXPECT_EQ(raw(2050), (std::vector<std::uint8_t>{0x78, 0x56, 0x34, 0x12}));
}

TEST(SiiBuild, AnExplicitStandardCategoryReplacesTheGeneratedOne) {
    const BuildResult r = build_fixture(fixture_xml("<Category><CatNo>41</CatNo><Data>0010800026000101</Data></Category>"));
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-category-explicit", Severity::info));
    const DecodedImage d = decode_image(r.bytes);
    std::size_t sync_m = 0;
    for (const auto& c : d.image.categories) sync_m += c.type == category::sync_manager;
    EXPECT_EQ(sync_m, 1u);
    ASSERT_EQ(d.image.sync_managers()->items.size(), 1u);
    const BuildResult odd = build_fixture(fixture_xml("<Category><CatNo>41</CatNo><Data>000018800026000101</Data></Category>"));
    EXPECT_TRUE(has_rule(odd.diagnostics, "sii-category-explicit", Severity::warning));  // 9 bytes: not whole records
}

TEST(SiiBuild, EepromDataIsUsedAsItIs) {
    const std::string data = "0102030405060708";
    const esi::test::Fixture f = esi::test::load_fixture(fixture_xml("<Data>" + data + "</Data>"));
    const BuildResult r = build_image(f.info(), f.device(), {}, "fixture.xml");
    EXPECT_TRUE(r.from_eeprom_data);
    EXPECT_EQ(r.bytes, (std::vector<std::uint8_t>{1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-eeprom-data", Severity::info));
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-eeprom-data-fault", Severity::warning));  // 8 bytes is no image
}

TEST(SiiBuild, ImageLargerThanByteSizeIsAnErrorWithStrictSize) {
    BuildOptions strict;
    strict.fit_to_eeprom = false;
    const BuildResult r = build_fixture(fixture_xml({}, "256"), strict);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-image-too-large", Severity::error));
    EXPECT_EQ(r.bytes.size(), r.content_bytes);  // not padded, still inspectable
    BuildOptions small = strict;
    small.include_pdos = false;
    small.include_dc = false;
    EXPECT_TRUE(build_fixture(fixture_xml({}, "256"), small).ok());
}

TEST(SiiBuild, ByteSizeTheSizeWordCannotExpress) {
    for (const std::string bad : {"100", "1000", "64"}) {
        SCOPED_TRACE(bad);
        EXPECT_TRUE(has_rule(build_fixture(fixture_xml({}, bad)).diagnostics, "sii-byte-size", Severity::error));
    }
    const BuildResult odd_size = build_fixture(fixture_xml({}, "1920"));  // 15 * 128: not a power of two, fine
    EXPECT_TRUE(odd_size.ok());
    EXPECT_EQ(decode_image(odd_size.bytes).image.header.size, 14);
}

TEST(SiiBuild, WithoutByteSizeTheSmallestPowerOfTwoIsDeclared) {
    const BuildResult r = build_fixture(fixture_xml({}, ""));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-byte-size", Severity::info));
    EXPECT_GT(r.content_bytes, 256u);
    EXPECT_LE(r.content_bytes, 512u);
    EXPECT_EQ(r.eeprom_bytes, 512u);
    EXPECT_EQ(r.bytes.size(), 512u);
}

TEST(SiiBuild, StringLongerThan255BytesIsAnError) {
    const std::string long_name(256, 'x');
    const std::string xml = fixture_xml();
    std::string edited = xml;
    edited.replace(edited.find("Test device 100"), 15, long_name);
    const BuildResult r = build_fixture(edited);
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-string-too-long", Severity::error));
    std::string edited255 = xml;
    edited255.replace(edited255.find("Test device 100"), 15, std::string(255, 'y'));
    EXPECT_TRUE(build_fixture(edited255).ok());
}

TEST(SiiBuild, MoreThan255StringsIsAnError) {
    std::string pdos;
    for (int i = 0; i < 300; ++i)
        pdos += "<TxPdo><Index>#x" + std::to_string(1000 + i) + "</Index><Name>PDO " + std::to_string(i) + "</Name></TxPdo>";
    std::string xml = fixture_xml({}, "");
    xml.insert(xml.find("<Mailbox"), pdos);
    BuildOptions strict;
    strict.fit_to_eeprom = false;
    const BuildResult r = build_fixture(xml, strict);
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-too-many-strings", Severity::error));
    BuildOptions no_pdo = strict;
    no_pdo.include_pdos = false;
    EXPECT_TRUE(build_fixture(xml, no_pdo).ok());
}

TEST(SiiBuild, ValuesTooWideForTheirFieldAreErrors) {
    std::string xml = fixture_xml();
    xml.replace(xml.find("<BitLen>16</BitLen>"), 19, "<BitLen>300</BitLen>");
    EXPECT_TRUE(has_rule(build_fixture(xml).diagnostics, "sii-value-range", Severity::error));
    std::string wide_sm = fixture_xml();
    wide_sm.replace(wide_sm.find("StartAddress=\"#x1100\""), 21, "StartAddress=\"#x11000\"");
    EXPECT_TRUE(has_rule(build_fixture(wide_sm).diagnostics, "sii-value-range", Severity::error));
}

TEST(SiiBuild, MoreThan255EntriesInAPdoIsAnError) {
    std::string entries;
    for (int i = 0; i < 256; ++i) entries += "<Entry><Index>0</Index><BitLen>1</BitLen></Entry>";
    std::string xml = fixture_xml({}, "");
    xml.insert(xml.find("</RxPdo>"), entries);
    EXPECT_TRUE(has_rule(build_fixture(xml).diagnostics, "sii-pdo-entries", Severity::error));
}

TEST(SiiBuild, LongConfigDataAndBadBootStrapAreReported) {
    std::string xml = fixture_xml();
    xml.replace(xml.find("0E05030610270000"), 16, "0E0503061027000000000000000000001122");
    xml.replace(xml.find("0010000200120002"), 16, "00100002");
    const BuildResult r = build_fixture(xml);
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-config-data", Severity::warning));
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-boot-strap", Severity::error));
}

TEST(SiiBuild, UnknownPhysicsLettersAndFmmuTypesAreReported) {
    std::string xml = fixture_xml();
    xml.replace(xml.find("Physics=\"YYK\""), 13, "Physics=\"YBK\"");
    xml.replace(xml.find("<Fmmu>MBoxState</Fmmu>"), 22, "<Fmmu>OrbitaState</Fmmu>");
    const BuildResult r = build_fixture(xml);
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-physics", Severity::warning));
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-fmmu-type", Severity::warning));
    const DecodedImage d = decode_image(r.bytes);
    EXPECT_EQ(d.image.general()->physical_ports, 0x0301);
}

TEST(SiiBuild, OutputIsDeterministic) {
    EXPECT_EQ(build_fixture(fixture_xml()).bytes, build_fixture(fixture_xml()).bytes);
}

TEST(SiiMapping, PhysicsSmAndFmmuCodes) {
    EXPECT_EQ(port_code('Y'), 1);
    EXPECT_EQ(port_code('H'), 1);
    EXPECT_EQ(port_code('K'), 3);
    EXPECT_EQ(port_code(' '), 0);
    EXPECT_FALSE(port_code('B').has_value());
    EXPECT_EQ(sm_type_code("MBoxOut"), 1);
    EXPECT_EQ(sm_type_code(" Inputs "), 4);
    EXPECT_EQ(sm_type_code(""), 0);
    EXPECT_FALSE(sm_type_code("OrbitaIn").has_value());
    EXPECT_EQ(fmmu_usage_code("MBoxState"), 3);
    EXPECT_EQ(fmmu_usage_code("DynamicOutputs"), 1);
    EXPECT_TRUE(same_pdo_data_type(0x1E, 0x05));
    EXPECT_TRUE(same_pdo_data_type(0x07, 0x20));
    EXPECT_FALSE(same_pdo_data_type(0x05, 0x02));
}

}  // namespace
