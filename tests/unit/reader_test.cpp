#include <gtest/gtest.h>

#include "esi/xml/reader.hpp"

namespace {

esi::ReadResult read(const std::string& xml) { return esi::read_esi(xml, "test.xml"); }

const esi::Diagnostic* find(const esi::ReadResult& r, std::string_view rule) {
    for (const auto& d : r.diagnostics)
        if (d.rule == rule) return &d;
    return nullptr;
}

const char* minimal_device = R"(<?xml version="1.0"?>
<EtherCATInfo Version="1.17">
  <Vendor><Id>#x0E4A</Id><Name>Example</Name></Vendor>
  <Descriptions>
    <Groups><Group><Type>IO</Type><Name LcId="1033">I/O</Name><Name LcId="1031">E/A</Name></Group></Groups>
    <Devices>
      <Device Physics="YY">
        <Type ProductCode="#x4711" RevisionNo="65538">  Example IO  </Type>
        <Name LcId="1033">Example</Name>
        <Info><Electrical><EBusCurrent>120</EBusCurrent></Electrical></Info>
        <GroupType>IO</GroupType>
        <Sm StartAddress="#x1000" ControlByte="#x26" DefaultSize="128" Enable="1">MBoxOut</Sm>
        <RxPdo Fixed="true" Sm="2">
          <Index>#x1600</Index>
          <Name>Outputs</Name>
          <Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen><Name>Out 1</Name><DataType>BOOL</DataType></Entry>
          <Entry><Index>0</Index><BitLen>7</BitLen></Entry>
        </RxPdo>
        <Mailbox DataLinkLayer="1"><CoE SdoInfo="true" PdoAssign="0"><InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>08</Data></InitCmd></CoE><FoE/></Mailbox>
        <Dc><OpMode><Name>DC</Name><AssignActivate>#x300</AssignActivate><CycleTimeSync0 Factor="1">0</CycleTimeSync0></OpMode></Dc>
        <Eeprom><ByteSize>2048</ByteSize><ConfigData>080E00CC0000</ConfigData></Eeprom>
        <VendorSpecific><Thing a="b">text</Thing></VendorSpecific>
      </Device>
    </Devices>
  </Descriptions>
</EtherCATInfo>
)";

}  // namespace

TEST(Reader, ReadsTypedModel) {
    const auto r = read(minimal_device);
    ASSERT_TRUE(r.document) << (r.diagnostics.empty() ? "" : r.diagnostics.items()[0].message);
    EXPECT_TRUE(r.diagnostics.empty());
    const auto& info = r.document->infos.at(0);
    EXPECT_EQ(info.version, "1.17");
    EXPECT_EQ(info.vendor->id, 0x0E4Au);
    ASSERT_EQ(info.groups.size(), 1u);
    EXPECT_EQ(info.groups[0].names.size(), 2u);
    EXPECT_EQ(esi::primary_text(info.groups[0].names), "I/O");
    const auto& d = info.devices.at(0);
    EXPECT_EQ(d.physics, "YY");
    EXPECT_EQ(d.type.product_code, 0x4711u);
    EXPECT_EQ(d.type.revision_no, 65538u);
    EXPECT_EQ(d.type.text, "Example IO");  // surrounding whitespace trimmed
    EXPECT_EQ(d.group_type, "IO");
    ASSERT_EQ(d.sms.size(), 1u);
    EXPECT_EQ(d.sms[0].control_byte, 0x26u);
    EXPECT_EQ(d.sms[0].default_size, 128u);
    ASSERT_EQ(d.rx_pdos.size(), 1u);
    EXPECT_EQ(d.rx_pdos[0].index, 0x1600u);
    EXPECT_EQ(d.rx_pdos[0].fixed, true);
    EXPECT_EQ(d.rx_pdos[0].sm, 2u);
    ASSERT_EQ(d.rx_pdos[0].entries.size(), 2u);
    EXPECT_TRUE(d.rx_pdos[0].entries[1].is_padding());
    EXPECT_EQ(d.rx_pdos[0].bit_size(), 8u);
    ASSERT_TRUE(d.mailbox && d.mailbox->coe);
    EXPECT_EQ(d.mailbox->data_link_layer, true);
    EXPECT_EQ(d.mailbox->coe->sdo_info, true);
    EXPECT_EQ(d.mailbox->coe->pdo_assign, false);
    EXPECT_EQ(d.mailbox->protocol_bits(), 0x04 | 0x08);
    ASSERT_EQ(d.mailbox->coe->init_cmds.size(), 1u);
    EXPECT_EQ(d.mailbox->coe->init_cmds[0].transitions.at(0).text, "PS");
    EXPECT_EQ(d.mailbox->coe->init_cmds[0].data.bytes(), std::vector<std::uint8_t>{8});
    ASSERT_TRUE(d.dc);
    EXPECT_EQ(d.dc->op_modes.at(0).assign_activate, 0x300u);
    EXPECT_EQ(d.dc->op_modes.at(0).cycle_time_sync0->factor, 1);
    ASSERT_TRUE(d.eeprom);
    EXPECT_EQ(d.eeprom->byte_size, 2048u);
    EXPECT_EQ(d.eeprom->config_data->byte_length(), 6u);
}

TEST(Reader, KeepsUnknownElementsVerbatimWithPosition) {
    const auto r = read(minimal_device);
    ASSERT_TRUE(r.document);
    const auto& d = r.document->infos[0].devices[0];
    const auto* info = d.extras.element("Info");
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->after, "Name");
    ASSERT_NE(d.extras.find("Info/Electrical/EBusCurrent"), nullptr);
    EXPECT_EQ(d.extras.find("Info/Electrical/EBusCurrent")->text, "120");
    const auto* vs = d.extras.element("VendorSpecific");
    ASSERT_NE(vs, nullptr);
    EXPECT_EQ(vs->children.at(0).attribute("a")->value, "b");
    EXPECT_EQ(vs->pos.line, 22u);
}

TEST(Reader, RecordsLineAndColumnOfElements) {
    const auto r = read(minimal_device);
    ASSERT_TRUE(r.document);
    const auto& d = r.document->infos[0].devices[0];
    EXPECT_EQ(d.pos.line, 7u);
    EXPECT_EQ(d.pos.column, 7u);
    EXPECT_EQ(d.rx_pdos[0].pos.line, 13u);
    EXPECT_EQ(d.rx_pdos[0].index_pos.line, 14u);
    EXPECT_EQ(d.rx_pdos[0].entries[0].pos.line, 16u);
}

TEST(Reader, ServoManualEndTagWithoutBracketIsOneSyntaxError) {
    const auto r = read("<?xml version=\"1.0\" ?>\n<EtherCATInfo Version=\"1.0\">\n<Name>Metronix ECAT</Name \n</EtherCATInfo>\n");
    EXPECT_FALSE(r.document);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.items()[0].rule, "xml-syntax");
    EXPECT_EQ(r.diagnostics.items()[0].severity, esi::Severity::error);
    EXPECT_EQ(r.diagnostics.items()[0].pos.line, 3u);
}

TEST(Reader, ServoManualIndexGluedToValueIsSyntaxErrorAtItsLine) {
    const auto r = read("<InitCmd>\n  <Transition>PS</Transition>\n  <Index#x6060</Index>\n</InitCmd>\n");
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.items()[0].rule, "xml-syntax");
    EXPECT_EQ(r.diagnostics.items()[0].pos.line, 3u);
}

TEST(Reader, ServoManualBlankInsideTagIsSyntaxError) {
    const auto r = read("<InitCmd>\n  < Data >03</Data>\n</InitCmd>\n");
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.items()[0].rule, "xml-syntax");
    EXPECT_EQ(r.diagnostics.items()[0].pos.line, 2u);
}

TEST(Reader, TruncatedFileIsSyntaxError) {
    const std::string text = minimal_device;
    const auto r = read(text.substr(0, text.size() / 2));
    EXPECT_FALSE(r.document);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.items()[0].rule, "xml-syntax");
}

TEST(Reader, EmptyInputIsSyntaxError) {
    const auto r = read("");
    EXPECT_FALSE(r.document);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.items()[0].rule, "xml-syntax");
}

TEST(Reader, NulByteIsSyntaxError) {
    const auto r = read(std::string("<EtherCATInfo>\0</EtherCATInfo>", 31));
    EXPECT_FALSE(r.document);
    EXPECT_NE(find(r, "xml-syntax"), nullptr);
}

TEST(Reader, CHexIsAcceptedWithWarning) {
    const auto r = read("<EtherCATInfo><Vendor><Id>0xF3F</Id></Vendor></EtherCATInfo>");
    ASSERT_TRUE(r.document);
    EXPECT_EQ(r.document->infos[0].vendor->id, 0xF3Fu);
    const auto* d = find(r, "xml-hex-prefix");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->severity, esi::Severity::warning);
}

TEST(Reader, BadNumberIsErrorAtTheElement) {
    const auto r = read("<EtherCATInfo>\n<Vendor>\n<Id>#x0x607F</Id></Vendor></EtherCATInfo>");
    const auto* d = find(r, "xml-number-format");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->pos.line, 3u);
    EXPECT_FALSE(r.document->infos[0].vendor->id.has_value());
}

TEST(Reader, OutOfRangeNumberIsReported) {
    const auto r = read(R"(<EtherCATInfo><Descriptions><Devices><Device><Type ProductCode="#x1FFFFFFFF"/></Device></Devices></Descriptions></EtherCATInfo>)");
    EXPECT_NE(find(r, "xml-number-range"), nullptr);
}

TEST(Reader, BadBooleanIsReported) {
    const auto r = read(R"(<EtherCATInfo><Descriptions><Devices><Device><Type/><RxPdo Fixed="yes"><Index>#x1600</Index></RxPdo></Device></Devices></Descriptions></EtherCATInfo>)");
    EXPECT_NE(find(r, "xml-boolean-format"), nullptr);
}

TEST(Reader, Latin1UmlautsComeOutAsUtf8) {
    const auto r = read("<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><EtherCATInfo><Vendor><Id>1</Id><Name>St\xF6" "ber</Name></Vendor></EtherCATInfo>");
    ASSERT_TRUE(r.document);
    EXPECT_EQ(r.document->infos[0].vendor->names.at(0).text, "St\xC3\xB6" "ber");
    EXPECT_TRUE(r.diagnostics.empty());
}

TEST(Reader, InvalidUtf8IsEncodingErrorButReadingGoesOn) {
    const auto r = read("<EtherCATInfo>\n<Vendor><Id>1</Id><Name>Schlie\xDF" "er</Name></Vendor></EtherCATInfo>");
    const auto* d = find(r, "xml-encoding");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->pos.line, 2u);
    ASSERT_TRUE(r.document);
    EXPECT_EQ(r.document->infos[0].vendor->id, 1u);
}

TEST(Reader, Utf16FileIsRead) {
    const std::string ascii = "<EtherCATInfo><Vendor><Id>7</Id></Vendor></EtherCATInfo>";
    std::string utf16 = "\xFF\xFE";
    for (char c : ascii) {
        utf16.push_back(c);
        utf16.push_back('\0');
    }
    const auto r = read(utf16);
    ASSERT_TRUE(r.document);
    EXPECT_EQ(r.document->infos[0].vendor->id, 7u);
    EXPECT_EQ(r.document->encoding, esi::SourceEncoding::utf16le);
}

TEST(Reader, EntitiesAreNeverExpanded) {
    const auto r = read(R"(<?xml version="1.0"?>
<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">]>
<EtherCATInfo><Vendor><Id>1</Id><Name>&lol2;</Name></Vendor></EtherCATInfo>)");
    ASSERT_TRUE(r.document);
    EXPECT_LT(r.document->infos[0].vendor->names.at(0).text.size(), 16u);
}

TEST(Reader, OtherRoots) {
    const auto dict = read("<EtherCATDict><Dictionary><Objects><Object><Index>#x1000</Index><Name>Device type</Name><Type>UDINT</Type><BitSize>32</BitSize></Object></Objects></Dictionary></EtherCATDict>");
    ASSERT_TRUE(dict.document);
    EXPECT_EQ(dict.document->kind, esi::DocumentKind::ethercat_dict);
    EXPECT_EQ(dict.document->dictionary->objects.at(0).index, 0x1000u);

    const auto module = read("<EtherCATModule><Vendor><Id>2</Id></Vendor><Modules><Module><Type ModuleIdent=\"#x10\">M</Type></Module></Modules></EtherCATModule>");
    ASSERT_TRUE(module.document);
    EXPECT_EQ(module.document->kind, esi::DocumentKind::ethercat_module);
    EXPECT_EQ(module.document->infos.at(0).modules.at(0).module_ident, 0x10u);

    const auto list = read("<EtherCATInfoList><EtherCATInfo><Vendor><Id>1</Id></Vendor></EtherCATInfo><EtherCATInfo><Vendor><Id>2</Id></Vendor></EtherCATInfo></EtherCATInfoList>");
    ASSERT_TRUE(list.document);
    EXPECT_EQ(list.document->infos.size(), 2u);

    const auto other = read("<Foo/>");
    EXPECT_NE(find(other, "xml-unknown-root"), nullptr);

    // Diagnosis messages (EtherCATDiag.xsd) are an ETG root that describes no device.
    const auto diag = read("<EtherCATDiag Version=\"1.0\"><DiagMessages><DiagMessage><TextId>#x0001</TextId>"
                           "<MessageText><Text>Overtemperature</Text></MessageText></DiagMessage></DiagMessages></EtherCATDiag>");
    ASSERT_TRUE(diag.document);
    EXPECT_EQ(diag.document->kind, esi::DocumentKind::ethercat_diag);
    EXPECT_EQ(find(diag, "xml-unknown-root"), nullptr);
    EXPECT_TRUE(diag.document->infos.empty());
    ASSERT_EQ(diag.document->root_extras.elements.size(), 1u);
    EXPECT_EQ(diag.document->root_extras.elements[0].name, "DiagMessages");
}

TEST(Reader, HexBinaryWhitespaceIsRemoved) {
    const auto r = read("<EtherCATInfo><Vendor><Id>1</Id><ImageData16x14>424D\n  E600\n\n00 00</ImageData16x14></Vendor></EtherCATInfo>");
    ASSERT_TRUE(r.document);
    EXPECT_EQ(r.document->infos[0].vendor->images.image_data16x14->text, "424DE6000000");
}

TEST(Reader, DeepNestingOfUnknownElementsIsBounded) {
    std::string xml = "<EtherCATInfo><Vendor><Id>1</Id></Vendor><X>";
    for (int i = 0; i < 2000; ++i) xml += "<a>";
    for (int i = 0; i < 2000; ++i) xml += "</a>";
    xml += "</X></EtherCATInfo>";
    const auto r = read(xml);
    ASSERT_TRUE(r.document);
    EXPECT_NE(find(r, "xml-nesting-depth"), nullptr);
}

TEST(Reader, MissingFileIsIoError) {
    const auto r = esi::read_esi_file("/nonexistent/file.xml");
    EXPECT_FALSE(r.document);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics.items()[0].rule, "io-error");
}

TEST(Reader, SwapDataIsTheSchemaEnumerationAsWritten) {
    const auto r = read(R"(<EtherCATInfo><Descriptions><Devices><Device><Type/><RxPdo><Index>#x1600</Index><Entry><Index>#x7000</Index><BitLen>16</BitLen><DataType SwapData="Swap_HB_LB">UINT</DataType></Entry></RxPdo></Device></Devices></Descriptions></EtherCATInfo>)");
    ASSERT_TRUE(r.document);
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_EQ(r.document->infos[0].devices[0].rx_pdos[0].entries[0].data_type_swap_data, "Swap_HB_LB");
}

// DependOnSlot/DependOnSlotGroup are read the same way wherever the schema allows them: the
// Index of a PDO, of a PDO entry, of an InitCmd and of an Object, and a PDO's Exclude.
TEST(Reader, DependOnSlotIsReadOnEveryIndexThatCarriesIt) {
    const auto r = read(R"(<EtherCATInfo><Descriptions><Devices><Device><Type/>
<TxPdo><Index DependOnSlot="1" DependOnSlotGroup="0" Other="x">#x1A00</Index><Exclude DependOnSlotGroup="true">#x1A01</Exclude>
  <Entry><Index DependOnSlot="true">#x6000</Index><BitLen>1</BitLen></Entry></TxPdo>
<Mailbox><CoE><InitCmd><Transition>PS</Transition><Index DependOnSlotGroup="1">#x8000</Index><Data>01</Data></InitCmd></CoE></Mailbox>
<Profile><Dictionary><Objects><Object><Index OverwrittenByModule="1" DependOnSlot="0">#x6000</Index></Object></Objects></Dictionary></Profile>
</Device></Devices></Descriptions></EtherCATInfo>)");
    ASSERT_TRUE(r.document);
    EXPECT_TRUE(r.diagnostics.empty()) << r.diagnostics.items()[0].message;
    const auto& d = r.document->infos.at(0).devices.at(0);
    const auto& pdo = d.tx_pdos.at(0);
    EXPECT_EQ(pdo.index_depend_on_slot, true);
    EXPECT_EQ(pdo.index_depend_on_slot_group, false);
    EXPECT_TRUE(pdo.extras.attributes.empty());  // attributes of Index other than these are not kept
    EXPECT_EQ(pdo.excludes.at(0).depend_on_slot, std::nullopt);
    EXPECT_EQ(pdo.excludes.at(0).depend_on_slot_group, true);
    EXPECT_EQ(pdo.entries.at(0).index_depend_on_slot, true);
    EXPECT_EQ(pdo.entries.at(0).index_depend_on_slot_group, std::nullopt);
    const auto& cmd = d.mailbox->coe->init_cmds.at(0);
    EXPECT_EQ(cmd.index_depend_on_slot, std::nullopt);
    EXPECT_EQ(cmd.index_depend_on_slot_group, true);
    const auto& object = d.dictionary()->objects.at(0);
    EXPECT_EQ(object.index_depend_on_slot, false);
    EXPECT_EQ(object.index_overwritten_by_module, true);
}

TEST(Reader, BadDependOnSlotIsReportedAtItsIndex) {
    const auto r = read("<EtherCATInfo><Descriptions><Devices><Device><Type/>\n"
                        "<RxPdo><Index>#x1600</Index>\n<Exclude DependOnSlot=\"maybe\">#x1601</Exclude></RxPdo>\n"
                        "</Device></Devices></Descriptions></EtherCATInfo>");
    ASSERT_TRUE(r.document);
    const auto* d = find(r, "xml-boolean-format");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->pos.line, 3u);
    EXPECT_NE(d->message.find("Exclude@DependOnSlot"), std::string::npos) << d->message;
    EXPECT_EQ(r.document->infos[0].devices[0].rx_pdos[0].excludes.at(0).depend_on_slot, std::nullopt);
}
