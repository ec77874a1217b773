// Derivation: what follows from the rest is filled in, explicit values win, and each part can
// be switched off.

#include <gtest/gtest.h>

#include "esi/model/typed_value.hpp"
#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::default_of;
using esi::test::describe;
using esi::test::load_yaml;
using esi::test::only_device;

namespace {

const std::string vendor = R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
)";

const std::string io_device = vendor + R"(devices:
  - type: D
    name: Device
    product_code: 0x1234
    revision: 0x00020001
    serial_no: 7
    mailbox: { size: 256, coe: { pdo_assign: false } }
    objects:
      0x6000: { name: In, type: UINT, access: ro, pdo: tx }
      0x7000: { name: Out, type: UDINT, access: rw, pdo: rx }
      0x7010: { name: Out 2, type: UINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, name: Out, entries: [0x7000] }
      - { index: 0x1601, name: Out 2, assigned: false, entries: [0x7010, pad16] }
    txpdo:
      - { index: 0x1A00, name: In, fixed: true, entries: [In] }
)";

DeviceSource load_ok(const std::string& text) {
    DeviceSource s = load_yaml(text);
    EXPECT_TRUE(s.diagnostics.empty()) << describe(s.diagnostics);
    EXPECT_TRUE(s.document.has_value());
    return s;
}

}  // namespace

TEST(YamlDerive, MailboxSmsFollowTheMailboxSize) {
    const DeviceSource s = load_ok(io_device);
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    ASSERT_EQ(d.sms.size(), 4u);
    EXPECT_EQ(d.sms[0].default_size, 256u);
    EXPECT_EQ(d.sms[1].default_size, 256u);
    EXPECT_EQ(d.sms[1].start_address, 0x1100u);  // after SM0's 256 bytes
    EXPECT_EQ(d.sms[2].start_address, 0x1200u);  // after both mailboxes
    EXPECT_EQ(d.sms[2].default_size, 4u);        // only 0x1600 is assigned by default
    EXPECT_EQ(d.sms[2].control_byte, 0x64u);     // watchdog trigger on the output SM
    EXPECT_EQ(d.sms[3].default_size, 2u);
    EXPECT_TRUE(d.mailbox->data_link_layer.value_or(false));
}

TEST(YamlDerive, PdoAssignmentAndAssignmentObjects) {
    const DeviceSource s = load_ok(io_device);
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    EXPECT_EQ(d.rx_pdos[0].sm, 2u);
    EXPECT_FALSE(d.rx_pdos[1].sm.has_value());
    // 0x1C12 lists both candidates, one assigned by default; it is writable because 0x1601 is
    // optional. 0x1C13 has its one fixed PDO assigned and nothing else: read-only.
    EXPECT_EQ(default_of(d, 0x1C12, 0), 1u);
    EXPECT_EQ(default_of(d, 0x1C12, 1), 0x1600u);
    EXPECT_EQ(default_of(d, 0x1C12, 2), 0u);
    ObjectLayout layout;
    const ObjectEntry* e = esi::test::object_entry(d, 0x1C12, 1, layout);
    ASSERT_TRUE(e && e->flags);
    EXPECT_EQ(e->flags->access, "rw");
    EXPECT_EQ(e->type, "UINT");
    e = esi::test::object_entry(d, 0x1C13, 1, layout);
    ASSERT_TRUE(e && e->flags);
    EXPECT_EQ(e->flags->access, "ro");
}

TEST(YamlDerive, MappingObjectsIncludePadding) {
    const DeviceSource s = load_ok(io_device);
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    EXPECT_EQ(default_of(d, 0x1601, 0), 2u);
    EXPECT_EQ(default_of(d, 0x1601, 1), 0x70100010u);
    EXPECT_EQ(default_of(d, 0x1601, 2), 0x00000010u);  // padding: index 0, 16 bits
    ObjectLayout layout;
    const ObjectEntry* e = esi::test::object_entry(d, 0x1A00, 1, layout);
    ASSERT_TRUE(e && e->flags);
    EXPECT_EQ(e->flags->access, "ro");  // a fixed PDO's mapping cannot be changed
    e = esi::test::object_entry(d, 0x1600, 1, layout);
    EXPECT_EQ(e->flags->access, "rw");
}

TEST(YamlDerive, IdentityAndDeviceType) {
    const DeviceSource s = load_ok(io_device);
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    EXPECT_EQ(default_of(d, 0x1018, 1), 0x10u);
    EXPECT_EQ(default_of(d, 0x1018, 2), 0x1234u);
    EXPECT_EQ(default_of(d, 0x1018, 3), 0x00020001u);
    EXPECT_EQ(default_of(d, 0x1018, 4), 7u);
    EXPECT_EQ(default_of(d, 0x1000, 0), 0u);  // no profile number
    EXPECT_EQ(default_of(d, 0x1C00, 0), 4u);
}

TEST(YamlDerive, ExplicitValuesWin) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 0x1234
    revision: 1
    profile: 401
    mailbox: { coe: true }
    objects:
      0x1000: { name: My device type, type: UDINT, access: ro, default: 0x12345678 }
      0x1018:
        name: Identity
        entries:
          1: { name: Vendor ID, type: UDINT, access: ro, default: 0x99 }
      0x7000: { name: Out, type: UINT, access: rw, pdo: rx }
    sms:
      - { type: MBoxOut, address: 0x1800, size: 64 }
      - { type: MBoxIn, address: 0x1900, size: 64 }
      - { type: Outputs, address: 0x1A00, size: 8, control_byte: 0x24 }
      - { type: Inputs, enable: false }
    fmmus: [Outputs]
    rxpdo:
      - { index: 0x1600, sm: 2, entries: [{ object: 0x7000, name: Renamed, data_type: UINT }] }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    EXPECT_EQ(default_of(d, 0x1000, 0), 0x12345678u);
    EXPECT_EQ(default_of(d, 0x1018, 1), 0x99u);
    ObjectLayout layout;
    EXPECT_EQ(esi::test::object_entry(d, 0x1018, 2, layout), nullptr);
    EXPECT_EQ(d.sms[0].start_address, 0x1800u);
    EXPECT_EQ(d.sms[0].default_size, 64u);
    EXPECT_EQ(d.sms[2].default_size, 8u);
    EXPECT_EQ(d.sms[2].control_byte, 0x24u);
    EXPECT_EQ(d.sms[3].enable, 0u);
    ASSERT_EQ(d.fmmus.size(), 1u);
    EXPECT_EQ(primary_text(d.rx_pdos[0].entries[0].names), "Renamed");
    EXPECT_EQ(d.rx_pdos[0].entries[0].bit_len, 16u);
}

TEST(YamlDerive, DeriveFalseKeepsTheModelAsWritten) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    derive: false
    mailbox: { coe: true }
    objects:
      0x7000: { name: Out, type: UINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, entries: [{ object: 0x7000, bit_len: 16, data_type: UINT, name: Out }] }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    EXPECT_TRUE(d.sms.empty());
    EXPECT_TRUE(d.fmmus.empty());
    EXPECT_FALSE(d.rx_pdos[0].sm.has_value());
    EXPECT_FALSE(d.mailbox->data_link_layer.has_value());
    ASSERT_TRUE(d.dictionary());
    EXPECT_EQ(d.dictionary()->objects.size(), 1u);
    EXPECT_TRUE(d.dictionary()->data_types.empty());
}

TEST(YamlDerive, DerivePartsCanBeSwitchedOffOneByOne) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    derive: { identity_object: false, mapping_objects: false, fmmus: false }
    mailbox: { coe: true }
    objects:
      0x7000: { name: Out, type: UINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, entries: [0x7000] }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    const Dictionary* od = d.dictionary();
    EXPECT_EQ(od->find_object(0x1018), nullptr);
    EXPECT_EQ(od->find_object(0x1600), nullptr);
    EXPECT_NE(od->find_object(0x1000), nullptr);
    EXPECT_NE(od->find_object(0x1C12), nullptr);
    EXPECT_TRUE(d.fmmus.empty());
    EXPECT_EQ(d.sms.size(), 4u);
}

TEST(YamlDerive, FlexiblePdosOfferTheDevicesMaximumOfEntries) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    mailbox: { coe: true }
    objects:
      0x7000: { name: Out, type: UINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, entries: [0x7000] }
      - { index: 0x1601, fixed: true, entries: [0x7000] }
    limits: { max_entries_per_pdo: 6 }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    ObjectLayout layout;
    EXPECT_NE(esi::test::object_entry(d, 0x1600, 6, layout), nullptr);
    EXPECT_EQ(esi::test::object_entry(d, 0x1600, 7, layout), nullptr);
    EXPECT_EQ(default_of(d, 0x1600, 0), 1u);
    EXPECT_EQ(esi::test::object_entry(d, 0x1601, 2, layout), nullptr);  // fixed: as many as it maps
}

TEST(YamlDerive, RecordsArraysAndTypedDefaults) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    mailbox: { coe: true }
    objects:
      0x2000:
        name: Gains
        entries:
          1: { name: Kp, type: REAL, access: rw, default: 1.5 }
          2: { name: Enable, type: BOOL, access: rw, default: true }
          3: { name: Limit, type: INT, access: rw, default: -300, min: -1000, max: 1000 }
      0x2001: { name: Label, type: STRING(8), access: rw, default: axis 1 }
      0x2002:
        name: Table
        type: UINT
        array: 3
        access: rw
        entries:
          2: { name: Second, default: 0x1234 }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    ObjectLayout layout;
    const ObjectEntry* kp = esi::test::object_entry(d, 0x2000, 1, layout);
    ASSERT_TRUE(kp && kp->info && kp->info->default_data);
    EXPECT_EQ(kp->info->default_data->text, "0000C03F");  // 1.5f little-endian
    EXPECT_EQ(kp->bit_offset, 16u);
    const ObjectEntry* enable = layout.entry(2);
    EXPECT_EQ(enable->bit_offset, 48u);
    EXPECT_EQ(enable->info->default_value, Number::from_unsigned(1));
    const ObjectEntry* limit = layout.entry(3);
    EXPECT_EQ(limit->bit_offset, 56u);  // byte-aligned after the BOOL
    EXPECT_EQ(limit->info->default_value, Number::from_signed(-300));
    EXPECT_EQ(limit->info->min_value, Number::from_signed(-1000));

    const ObjectEntry* label = esi::test::object_entry(d, 0x2001, 0, layout);
    ASSERT_TRUE(label && label->info);
    EXPECT_EQ(label->info->default_string, "axis 1");
    EXPECT_EQ(label->bit_size, 64u);
    EXPECT_NE(d.dictionary()->find_data_type("STRING(8)"), nullptr);

    const Object* table = d.dictionary()->find_object(0x2002);
    ASSERT_TRUE(table);
    layout = layout_of(d.dictionary(), *table);
    EXPECT_EQ(layout.code, ObjectCode::array);
    ASSERT_EQ(layout.entries.size(), 4u);
    EXPECT_EQ(layout.entries[2].name, "Second");
    EXPECT_EQ(layout.entries[2].info->default_value, Number::from_unsigned(0x1234));
    EXPECT_EQ(layout.entries[0].info->default_value, Number::from_unsigned(3));
}

TEST(YamlDerive, DeclaredStructuredTypesTakeValuesPerEntry) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    mailbox: { coe: true }
    data_types:
      - name: DT6000
        sub_items:
          - { subindex: 0, name: SubIndex 000, type: USINT, bit_size: 8, bit_offset: 0, access: ro }
          - { subindex: 1, name: Value, type: INT, bit_size: 16, bit_offset: 16, access: ro, pdo: tx }
    objects:
      0x6000: { name: Channel 1, type: DT6000, entries: { 0: { default: 1 }, 1: { default: -5 } } }
      0x6010: { name: Channel 2, type: DT6000, entries: { 0: { default: 1 } } }
    txpdo:
      - { index: 0x1A00, entries: ["0x6000:1", "0x6010:1"] }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    const DataType* t = d.dictionary()->find_data_type("DT6000");
    ASSERT_TRUE(t);
    EXPECT_EQ(t->bit_size, 32u);
    EXPECT_EQ(default_of(d, 0x6000, 0), 1u);
    ObjectLayout layout;
    const ObjectEntry* v = esi::test::object_entry(d, 0x6000, 1, layout);
    ASSERT_TRUE(v && v->info);
    EXPECT_EQ(v->info->default_value, Number::from_signed(-5));
    EXPECT_EQ(d.tx_pdos[0].entries[1].data_type, "INT");
    EXPECT_EQ(primary_text(d.tx_pdos[0].entries[1].names), "Value");
}

TEST(YamlDerive, GroupsAreDerivedWhenNotDeclared) {
    const DeviceSource s = load_ok(R"(vendor: { id: 1, name: V }
devices:
  - { type: D, name: D, product_code: 1, revision: 1, group: Sensors }
)");
    ASSERT_TRUE(s.document);
    ASSERT_EQ(s.document->infos[0].groups.size(), 1u);
    EXPECT_EQ(s.document->infos[0].groups[0].type, "Sensors");
    EXPECT_EQ(only_device(s).physics, "YY");
}

TEST(YamlDerive, EscapeHatchKeepsVerbatimXml) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    type_xml: { attributes: { CheckRevisionNo: EQ_OR_G } }
    xml:
      elements:
        - <Info><StateMachine><Timeout><PreopTimeout>2000</PreopTimeout></Timeout></StateMachine></Info>
        - { after: Mailbox, xml: "<VendorSpecific><Tool a='1'>x</Tool></VendorSpecific>" }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    ASSERT_EQ(d.type.extras.attributes.size(), 1u);
    EXPECT_EQ(d.type.extras.attributes[0].value, "EQ_OR_G");
    ASSERT_EQ(d.extras.elements.size(), 2u);
    const XmlElement* timeout = d.extras.find("Info/StateMachine/Timeout/PreopTimeout");
    ASSERT_TRUE(timeout);
    EXPECT_EQ(timeout->text, "2000");
    EXPECT_EQ(d.extras.elements[1].after, "Mailbox");
    EXPECT_EQ(d.extras.elements[1].children.at(0).attributes.at(0).value, "1");
    EXPECT_EQ(d.extras.elements[0].pos.line, 11u);
}

TEST(TypedValue, EncodesLittleEndianInTheObjectsSize) {
    auto integer = [](std::int64_t v) {
        SourceValue s;
        s.kind = SourceValue::Kind::integer;
        s.integer = Number::from_signed(v);
        s.text = std::to_string(v);
        return s;
    };
    auto type = [](const char* name, std::uint64_t bits = 0) {
        ValueType t;
        t.basic = parse_type_name(name).basic;
        t.bit_size = bits ? bits : t.basic->bit_size;
        return t;
    };
    auto hex = [](const EncodedValue& e) { return HexData::from_bytes(e.bytes).text; };
    EXPECT_EQ(hex(encode_value(integer(8), type("SINT"))), "08");
    EXPECT_EQ(hex(encode_value(integer(-1), type("SINT"))), "FF");
    EXPECT_EQ(hex(encode_value(integer(0x1600), type("UINT"))), "0016");
    EXPECT_EQ(hex(encode_value(integer(-2), type("DINT"))), "FEFFFFFF");
    EXPECT_EQ(hex(encode_value(integer(5), type("BIT3"))), "05");
    EXPECT_FALSE(encode_value(integer(8), type("BIT3")).ok());
    EXPECT_FALSE(encode_value(integer(-1), type("USINT")).ok());
    EXPECT_FALSE(encode_value(integer(128), type("SINT")).ok());
    EXPECT_TRUE(encode_value(integer(-128), type("SINT")).ok());

    SourceValue real;
    real.kind = SourceValue::Kind::real;
    real.real = -2.0;
    real.text = "-2.0";
    EXPECT_EQ(hex(encode_value(real, type("REAL"))), "000000C0");
    EXPECT_EQ(hex(encode_value(real, type("LREAL"))), "00000000000000C0");
    EXPECT_FALSE(encode_value(real, type("UINT")).ok());

    SourceValue text;
    text.text = "abc";
    EXPECT_EQ(hex(encode_value(text, type("STRING(3)", 24))), "616263");
    text.text = "abcd";
    EXPECT_FALSE(encode_value(text, type("STRING(3)", 24)).ok());
}

TEST(YamlFormat, ModuleDescriptionFiles) {
    const DeviceSource s = load_ok(R"(root_element: EtherCATModule
vendor: { id: 2, name: Example }
modules:
  - type: M-1
    ident: 0x100
    name: Module 1
    txpdo: [{ index: 0x1A00, entries: [{ object: 0x6000, bit_len: 16, data_type: INT, name: Value }] }]
)");
    ASSERT_TRUE(s.document);
    EXPECT_EQ(s.document->kind, DocumentKind::ethercat_module);
    EXPECT_TRUE(s.document->infos[0].devices.empty());
    ASSERT_EQ(s.document->infos[0].modules.size(), 1u);
    const DeviceSource bad = load_yaml(R"(root_element: EtherCATModul
vendor: { id: 2, name: Example }
devices: []
)");
    EXPECT_FALSE(bad.document);
}

TEST(YamlFormat, PaddingKeepsASubindexAsWritten) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    rxpdo: [{ index: 0x1600, entries: [{ pad: 8, subindex: 0 }, pad8] }]
)");
    ASSERT_TRUE(s.document);
    const auto& entries = only_device(s).rx_pdos[0].entries;
    ASSERT_EQ(entries.size(), 2u);
    EXPECT_EQ(entries[0].subindex, 0u);
    EXPECT_FALSE(entries[1].subindex.has_value());
    EXPECT_EQ(entries[0].bit_len, 8u);
}

// ETG.1000.6: sub-index 0 of an ARRAY/RECORD is the UNSIGNED8 number of entries. A record that
// writes a sub-index 0 of another type holds data there (STÖBER A261.0, the UDINT sync error
// code, where 2 means "cycle time < 1 ms"); it gets no count as its default. An explicit USINT
// sub-index 0 without a value is the count.
TEST(YamlDerive, RecordSubindexZeroGetsTheCountOnlyWhenItIsOne) {
    const DeviceSource s = load_ok(vendor + R"(devices:
  - type: D
    name: Device
    product_code: 1
    revision: 1
    mailbox: { coe: true }
    objects:
      0x2105:
        name: A261 EtherCAT Sync-Diagnose
        entries:
          0: { name: Element 0 (error code), type: UDINT, access: ro }
          1: { name: Element 1 (reserved), type: UDINT, access: ro }
          2: { name: Element 2 (sync errors), type: UDINT, access: ro }
      0x2106:
        name: Counted
        entries:
          0: { name: Number of entries, type: USINT, access: ro }
          1: { name: First, type: UINT, access: ro }
          2: { name: Second, type: UINT, access: ro }
)");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    ObjectLayout layout;
    const ObjectEntry* error_code = esi::test::object_entry(d, 0x2105, 0, layout);
    ASSERT_NE(error_code, nullptr);
    EXPECT_TRUE(!error_code->info || (!error_code->info->default_value && !error_code->info->default_data));
    const ObjectEntry* count = esi::test::object_entry(d, 0x2106, 0, layout);
    ASSERT_TRUE(count && count->info);
    EXPECT_EQ(count->info->default_value, Number::from_unsigned(2));
}
