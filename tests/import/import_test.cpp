// esi::import_device_source (esi-gen --import as a library): texts that YAML would read as
// something else survive, derived parts are left out exactly when derivation reproduces them and
// kept explicit otherwise, --device selects, unmodelled XML goes through the escape hatch, and
// the output is deterministic. The corpus-wide round trip is import_corpus_test.cpp.

#include <gtest/gtest.h>

#include "esi/diff/diff.hpp"
#include "esi/import/import.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "esi/yaml/source.hpp"
#include "import/yaml_emitter.hpp"
#include "support/test_support.hpp"

namespace {

using esi::DeviceSelector;
using esi::EsiDocument;
using esi::import_device_source;
using esi::ImportOptions;
using esi::ImportResult;

EsiDocument load_sample(const std::string& name) {
    esi::DeviceSource s = esi::load_device_source_file(esi::test::source_dir() / "samples" / name);
    EXPECT_TRUE(s.document) << name;
    return std::move(*s.document);
}

std::string diagnostics_text(const esi::Diagnostics& ds) {
    std::string out;
    for (const auto& d : ds) out += std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.rule + " " + d.message + "\n";
    return out;
}

// import -> YAML -> load -> write_esi -> read_esi, compared with the original; "" when identical.
std::string round_trip_changes(const EsiDocument& original, const ImportOptions& options = {}) {
    const ImportResult imported = import_device_source(original, options);
    if (!imported.yaml) return "import failed: " + diagnostics_text(imported.diagnostics);
    const esi::DeviceSource loaded = esi::load_device_source(*imported.yaml, "imported.yaml");
    if (!loaded.document) return "load failed: " + diagnostics_text(loaded.diagnostics) + *imported.yaml;
    const esi::ReadResult again = esi::read_esi(esi::write_esi(*loaded.document), "regenerated.xml");
    if (!again.document) return "regenerated XML not read";
    const esi::DiffResult diff = esi::diff_documents(original, *again.document);
    std::string out;
    for (const auto& c : diff.changes) out += c.path + ": " + c.message + "\n";
    return out;
}

esi::Device& first_device(EsiDocument& d) { return d.infos.at(0).devices.at(0); }

TEST(ImportQuoting, PlainOnlyWhenYamlReadsTheSameText) {
    using esi::import_detail::quote_text;
    EXPECT_EQ(quote_text("Digital I/O"), "Digital I/O");
    EXPECT_EQ(quote_text("Outputs"), "Outputs");
    for (const char* special : {"yes", "No", "on", "OFF", "y", "~", "null", "true", "", "#1", "*ref", "&anchor", "a: b",
                                "1234", "0x10", "-5", " lead", "trail ", "!tag", "%x", "@x", "`x", "[x]", "{x}", "x, y",
                                "a #b", "|", ">", "?", "'", "\"q\""}) {
        SCOPED_TRACE(special);
        EXPECT_EQ(quote_text(special).front(), '"');
    }
    EXPECT_EQ(quote_text("line\nbreak\t\"q\" \\"), "\"line\\nbreak\\t\\\"q\\\" \\\\\"");
    EXPECT_EQ(quote_text("Ausgänge"), "\"Ausgänge\"");      // non-ASCII kept as UTF-8, quoted
    EXPECT_EQ(quote_text(std::string("a\x01z")), "\"a\\x01z\"");  // not printable in YAML: escaped
}

TEST(ImportQuoting, TextsSurviveTheRoundTrip) {
    EsiDocument doc = load_sample("digital-io-8.yaml");
    esi::Device& d = first_device(doc);
    const std::vector<std::string> texts = {"yes", "no", "on", "off", "~", "null", "#1 channel", "*star", "&amp; co",
                                            "a: b", "Ünïcode ✓ 日本", "1234", "0x1F", "  leading blank", "tab\there",
                                            "line\nbreak", "\"quoted\"", "back\\slash", "- dash", "? question", "% percent"};
    d.names.clear();
    for (std::size_t i = 0; i < texts.size(); ++i)
        d.names.push_back(esi::LocalizedText{texts[i], static_cast<std::uint32_t>(1000 + i), {}});
    d.comments = {esi::LocalizedText{"yes", std::nullopt, {}}};
    d.rx_pdos.at(0).names = {esi::LocalizedText{"no", std::nullopt, {}}};
    EXPECT_EQ(round_trip_changes(doc), "");
    const ImportResult imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml);
    EXPECT_NE(imported.yaml->find("\"yes\""), std::string::npos);
    EXPECT_NE(imported.yaml->find("\"tab\\there\""), std::string::npos);
}

TEST(ImportDerivation, DerivedPartsOfAnEsiGenFileAreLeftOut) {
    const EsiDocument doc = load_sample("digital-io-8.yaml");
    const ImportResult imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml) << diagnostics_text(imported.diagnostics);
    const std::string& y = *imported.yaml;
    EXPECT_EQ(imported.derived_devices, 1u);
    // SMs, FMMUs, 0x1000, 0x1018, 0x1600/0x1A00, 0x1C00, 0x1C12/0x1C13 and the DataTypes come back by derivation.
    for (const char* omitted : {"sms:", "fmmus:", "0x1000:", "0x1018:", "0x1600:", "0x1A00:", "0x1C00:", "0x1C12:", "0x1C13:",
                                "DT1018", "DT1C00", "DT1600", "derive:", "bit_len:", "in_address"})
        EXPECT_EQ(y.find(omitted), std::string::npos) << omitted << "\n" << y;
    EXPECT_NE(y.find("size: 128"), std::string::npos) << y;  // the mailbox size the SMs derive from
    EXPECT_EQ(round_trip_changes(doc), "");
}

TEST(ImportDerivation, WhatTheFileHasDifferentlyStaysExplicit) {
    EsiDocument doc = load_sample("digital-io-8.yaml");
    esi::Device& d = first_device(doc);
    // An Inputs SM at an address derivation would not choose, and a 0x1018 serial number default
    // that differs from the derived one.
    for (auto& sm : d.sms)
        if (sm.type == "Inputs") sm.start_address = 0x1A00;
    esi::Dictionary& dict = *d.profiles.at(0).dictionary;
    for (auto& o : dict.objects)
        if (o.index == 0x1018) o.names = {esi::LocalizedText{"Identity (vendor text)", std::nullopt, {}}};
    const ImportResult imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml);
    const std::string& y = *imported.yaml;
    EXPECT_NE(y.find("sms:"), std::string::npos) << y;
    EXPECT_NE(y.find("address: 0x1A00"), std::string::npos) << y;
    EXPECT_NE(y.find("sync_managers: false"), std::string::npos) << y;
    EXPECT_NE(y.find("0x1018:"), std::string::npos) << y;
    EXPECT_NE(y.find("Identity (vendor text)"), std::string::npos) << y;
    EXPECT_NE(y.find("identity_object: false"), std::string::npos) << y;
    // Parts that still match are still left out.
    EXPECT_EQ(y.find("0x1C00:"), std::string::npos) << y;
    EXPECT_EQ(round_trip_changes(doc), "");
}

TEST(ImportEscPreset, ConfigDataOfAPresetBecomesEscAndAnyOtherStaysExplicit) {
    // modular-coupler names `esc: xmc4`: its ESI holds exactly the preset's ConfigData and size.
    EsiDocument doc = load_sample("modular-coupler.yaml");
    ImportResult imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml) << diagnostics_text(imported.diagnostics);
    EXPECT_NE(imported.yaml->find("    esc: xmc4\n"), std::string::npos) << *imported.yaml;
    EXPECT_EQ(imported.yaml->find("config_data:"), std::string::npos) << *imported.yaml;
    EXPECT_EQ(imported.yaml->find("eeprom:"), std::string::npos) << *imported.yaml;
    EXPECT_EQ(round_trip_changes(doc), "");

    // Another size: not the preset, so the three values stay as the file has them.
    first_device(doc).eeprom->byte_size = 4096;
    imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml);
    EXPECT_EQ(imported.yaml->find("esc:"), std::string::npos) << *imported.yaml;
    EXPECT_NE(imported.yaml->find("config_data: \"8006810600000000\""), std::string::npos) << *imported.yaml;
    EXPECT_EQ(round_trip_changes(doc), "");

    // A preset with a BootStrap matches only with that BootStrap; lower-case hex matches too.
    first_device(doc).eeprom->byte_size = 2048;
    first_device(doc).eeprom->config_data->text = "8006e08800000000";
    first_device(doc).eeprom->boot_strap = esi::HexData{"0010000200120002", {}};
    imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml);
    EXPECT_NE(imported.yaml->find("    esc: tiesc\n"), std::string::npos) << *imported.yaml;
    EXPECT_EQ(round_trip_changes(doc), "");
}

TEST(ImportDerivation, WithoutOmissionEverythingIsExplicit) {
    const EsiDocument doc = load_sample("servo-item-c-series.yaml");
    ImportOptions options;
    options.omit_derived = false;
    const ImportResult imported = import_device_source(doc, options);
    ASSERT_TRUE(imported.yaml);
    EXPECT_EQ(imported.derived_devices, 0u);
    EXPECT_NE(imported.yaml->find("derive: false"), std::string::npos);
    EXPECT_NE(imported.yaml->find("sms:"), std::string::npos);
    EXPECT_NE(imported.yaml->find("0x1018:"), std::string::npos);
    EXPECT_EQ(round_trip_changes(doc, options), "");
    EXPECT_EQ(round_trip_changes(doc), "");
}

TEST(ImportDevice, SelectorPicksOneDeviceAndReportsNoMatch) {
    EsiDocument doc = load_sample("digital-io-8.yaml");
    ASSERT_GE(doc.infos.at(0).devices.size(), 1u);
    esi::Device copy = first_device(doc);
    copy.type.product_code = 0x4711;
    copy.type.revision_no = 0x00020000;
    doc.infos.at(0).devices.push_back(copy);

    ImportOptions options;
    options.device = DeviceSelector{0x4711, std::nullopt};
    const ImportResult one = import_device_source(doc, options);
    ASSERT_TRUE(one.yaml) << diagnostics_text(one.diagnostics);
    EXPECT_EQ(one.devices, 1u);
    EXPECT_NE(one.yaml->find("product_code: 0x00004711"), std::string::npos);
    EXPECT_EQ(one.yaml->find("product_code: 0x00001002"), std::string::npos);
    const esi::DeviceSource loaded = esi::load_device_source(*one.yaml, "one.yaml");
    ASSERT_TRUE(loaded.document);
    EXPECT_EQ(loaded.document->infos.at(0).devices.size(), 1u);

    const ImportResult all = import_device_source(doc);
    EXPECT_EQ(all.devices, doc.infos.at(0).devices.size());

    options.device = DeviceSelector{0x9999, std::nullopt};
    const ImportResult none = import_device_source(doc, options);
    EXPECT_FALSE(none.yaml);
    ASSERT_FALSE(none.diagnostics.empty());
    EXPECT_EQ(none.diagnostics.begin()->rule, "import-device");
}

TEST(ImportEscapeHatch, UnmodelledXmlComesBackWhereItWas) {
    const std::string xml = R"(<?xml version="1.0"?>
<EtherCATInfo Version="1.6" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <Vendor><Id>#x0E4A</Id><Name>V &amp; Co</Name></Vendor>
  <Descriptions>
    <Groups><Group><Type>IO</Type><Name>IO</Name></Group></Groups>
    <Devices>
      <Device Physics="YY">
        <Type ProductCode="#x10" RevisionNo="#x1" CheckRevisionNo="EQ_OR_G">X1</Type>
        <Name>no</Name>
        <GroupType>IO</GroupType>
        <Fmmu>Outputs</Fmmu>
        <Sm StartAddress="#x1000" ControlByte="#x64" DefaultSize="1" Enable="1">Outputs</Sm>
        <RxPdo Fixed="1" Sm="0"><Index>#x1600</Index><Name>Out</Name>
          <Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>8</BitLen><Name>o</Name><DataType>USINT</DataType></Entry>
        </RxPdo>
        <Info><StateMachine><Timeout><PreopTimeout>2000</PreopTimeout></Timeout></StateMachine><Note a="x &lt; y">t</Note></Info>
        <VendorSpecific><Tool>yes</Tool></VendorSpecific>
      </Device>
    </Devices>
  </Descriptions>
</EtherCATInfo>
)";
    const esi::ReadResult read = esi::read_esi(xml, "x.xml");
    ASSERT_TRUE(read.document);
    const ImportResult imported = import_device_source(*read.document);
    ASSERT_TRUE(imported.yaml) << diagnostics_text(imported.diagnostics);
    EXPECT_NE(imported.yaml->find("CheckRevisionNo: EQ_OR_G"), std::string::npos) << *imported.yaml;
    EXPECT_NE(imported.yaml->find("after: RxPdo"), std::string::npos) << *imported.yaml;
    EXPECT_EQ(round_trip_changes(*read.document), "");
}

TEST(ImportOutput, DeterministicAndRejectsOtherRoots) {
    const EsiDocument doc = load_sample("modular-coupler.yaml");
    const ImportResult a = import_device_source(doc);
    const ImportResult b = import_device_source(doc);
    ASSERT_TRUE(a.yaml);
    EXPECT_EQ(*a.yaml, *b.yaml);
    EXPECT_EQ(round_trip_changes(doc), "");

    EsiDocument list = doc;
    list.kind = esi::DocumentKind::ethercat_info_list;
    list.infos.push_back(doc.infos.at(0));
    const ImportResult r = import_device_source(list);
    EXPECT_FALSE(r.yaml);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics.begin()->rule, "import-root");
}

TEST(ImportOutput, EveryYamlSampleRoundTrips) {
    for (const char* name : {"digital-io-8.yaml", "encoder-tr-linear.yaml", "inverter-stoeber-mds5000.yaml", "modular-coupler.yaml",
                             "servo-item-c-series.yaml"}) {
        SCOPED_TRACE(name);
        EXPECT_EQ(round_trip_changes(load_sample(name)), "");
    }
}

}  // namespace

// The `xml` escape hatch holds XML text: a C0 control or invalid UTF-8 in unmodelled XML becomes
// U+FFFD there, as in the ESI writer (esi/xml_text.hpp), so the fragment is well-formed XML 1.0
// and the YAML holds no escaped control character; an invalid byte does not turn into the Latin-1
// character of the same number on the way back.
TEST(ImportEscapeHatch, ControlCharactersAndInvalidUtf8BecomeReplacementCharacters) {
    EsiDocument doc = load_sample("digital-io-8.yaml");
    esi::XmlElement element;
    element.name = "Remark";
    element.attributes.push_back({"x", "a\x01" "b\xFF"});
    element.text = "t\x02" "ext\xC3";
    doc.infos.at(0).vendor->extras.elements.push_back(element);

    const ImportResult imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml) << diagnostics_text(imported.diagnostics);
    for (const char* escape : {"\\x01", "\\x02", "\\xFF", "\\xC3"})
        EXPECT_EQ(imported.yaml->find(escape), std::string::npos) << escape << "\n" << *imported.yaml;
    const esi::DeviceSource loaded = esi::load_device_source(*imported.yaml, "imported.yaml");
    ASSERT_TRUE(loaded.document) << diagnostics_text(loaded.diagnostics);
    const auto& elements = loaded.document->infos.at(0).vendor->extras.elements;
    ASSERT_EQ(elements.size(), 1u);
    const std::string r = "\xEF\xBF\xBD";  // U+FFFD
    EXPECT_EQ(elements[0].attributes.at(0).value, "a" + r + "b" + r);
    EXPECT_EQ(elements[0].text, "t" + r + "ext" + r);
}

namespace {

TEST(ImportIdentity, TwoDevicesWithOneIdentityAreNamedAtImport) {
    EsiDocument doc = load_sample("digital-io-8.yaml");
    esi::Device copy = first_device(doc);
    copy.type.text = "EX-DIO-8B-copy";
    copy.pos = esi::SourcePos{40, 5};
    copy.type.pos = esi::SourcePos{41, 7};
    first_device(doc).type.pos = esi::SourcePos{12, 7};
    doc.infos.at(0).devices.push_back(copy);
    const ImportResult imported = import_device_source(doc);
    ASSERT_TRUE(imported.yaml);
    const esi::Diagnostic* found = nullptr;
    for (const auto& d : imported.diagnostics)
        if (d.rule == "import-identity") found = &d;
    ASSERT_NE(found, nullptr) << diagnostics_text(imported.diagnostics);
    EXPECT_EQ(found->pos.line, 41u);
    ASSERT_EQ(found->notes.size(), 1u);
    EXPECT_EQ(found->notes[0].pos.line, 12u);
    // Loading the source refuses it, naming both places too.
    const esi::DeviceSource loaded = esi::load_device_source(*imported.yaml, "imported.yaml");
    EXPECT_FALSE(loaded.document);
}

}  // namespace
