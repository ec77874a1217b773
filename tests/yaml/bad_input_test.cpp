// Bad YAML input: every diagnostic kind at its exact line:col, and never a document when there
// are errors.

#include <gtest/gtest.h>

#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::describe;
using esi::test::load_yaml;

namespace {

// A valid minimal device; tests replace or append lines.
const std::string header = R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - type: D
    name: Device
    product_code: 1
    revision: 2
    mailbox: { size: 128, coe: true }
)";  // 8 lines; the next line is line 9

// Expects exactly one error with this rule at line:col and no document.
void expect_error(const DeviceSource& s, const std::string& rule, std::uint32_t line, std::uint32_t column,
                  const std::string& fragment = {}) {
    EXPECT_FALSE(s.document.has_value()) << "a document was returned despite errors";
    EXPECT_TRUE(s.diagnostics.has_errors());
    bool found = false;
    for (const auto& d : s.diagnostics) {
        if (d.rule == rule && d.pos.line == line && d.pos.column == column &&
            (fragment.empty() || d.message.find(fragment) != std::string::npos))
            found = true;
    }
    EXPECT_TRUE(found) << "expected " << rule << " at " << line << ":" << column << " (" << fragment << "), got:\n"
                       << describe(s.diagnostics);
    EXPECT_EQ(s.diagnostics.count(Severity::error), 1u) << describe(s.diagnostics);
}

}  // namespace

TEST(YamlBadInput, TheHeaderAloneIsValid) {
    const DeviceSource s = load_yaml(header);
    EXPECT_TRUE(s.diagnostics.empty()) << describe(s.diagnostics);
    EXPECT_TRUE(s.document.has_value());
}

TEST(YamlBadInput, SyntaxErrorIsLocated) {
    expect_error(load_yaml("vendor: { id: 1, name: x\ndevices: []\n"), "yaml-syntax", 2, 8, "did not find expected ',' or '}'");
    expect_error(load_yaml("vendor:\n\tid: 1\n"), "yaml-syntax", 2, 1, "cannot start any token");  // a tab indents
    expect_error(load_yaml("vendor: {id: 1, name: \"x\xff\"}\n"), "yaml-syntax", 1, 25, "UTF-8");
}

TEST(YamlBadInput, UnknownKeyHasDidYouMean) {
    const DeviceSource s = load_yaml(header + "    rxpdos: []\n");
    expect_error(s, "yaml-unknown-key", 9, 5, "did you mean 'rxpdo'?");
    // No suggestion when nothing is close.
    const DeviceSource far = load_yaml(header + "    zzzzzz: 1\n");
    expect_error(far, "yaml-unknown-key", 9, 5, "unknown key 'zzzzzz' in a device");
    EXPECT_EQ(far.diagnostics.items()[0].message.find("did you mean"), std::string::npos);
}

TEST(YamlBadInput, WrongTypesAreLocated) {
    expect_error(load_yaml(header + "    invisible: maybe\n"), "yaml-type", 9, 16, "true or false");
    expect_error(load_yaml(header + "    rxpdo: { index: 0x1600 }\n"), "yaml-type", 9, 12, "must be a list");
    expect_error(load_yaml(header + "    dc: [{ name: [a, b] }]\n"), "yaml-type", 9, 18, "must be text");
    expect_error(load_yaml(header + "    serial_no: twelve\n"), "yaml-type", 9, 16, "not an integer");
    expect_error(load_yaml(header + "    eeprom: { config_data: 0x0800 }\n"), "yaml-type", 9, 28, "not hex bytes");
    expect_error(load_yaml(header + "    eeprom: { config_data: 080 }\n"), "yaml-type", 9, 28, "odd number");
}

TEST(YamlBadInput, DuplicateKeysAreFoundThoughYamlCppAcceptsThem) {
    const DeviceSource s = load_yaml(header + "    physics: YY\n    physics: KK\n");
    expect_error(s, "yaml-duplicate-key", 10, 5, "duplicate key 'physics'");
    ASSERT_EQ(s.diagnostics.items()[0].notes.size(), 1u);
    EXPECT_EQ(s.diagnostics.items()[0].notes[0].pos.line, 9u);
    // 0x6000 and 24576 are one object index.
    const DeviceSource objects =
        load_yaml(header + "    objects:\n      0x6000: { name: A, type: UINT }\n      24576: { name: B, type: UINT }\n");
    expect_error(objects, "yaml-duplicate-key", 11, 7, "object 0x6000 is declared twice");
}

TEST(YamlBadInput, OutOfRangeNumbers) {
    expect_error(load_yaml(header + "    serial_no: 0x100000000\n"), "yaml-number-range", 9, 16, "out of range");
    expect_error(load_yaml(header + "    objects:\n      0x6000: { name: A, type: SINT, default: 128 }\n"), "yaml-number-range", 10,
                 47, "128 does not fit SINT");
    expect_error(load_yaml(header + "    objects:\n      0x10000: { name: A, type: UINT }\n"), "yaml-number-range", 10, 7,
                 "0..65535");
    expect_error(load_yaml(header + "    rxpdo: [{ index: 0x1600, sm: 40 }]\n"), "yaml-number-range", 9, 34);
}

TEST(YamlBadInput, BillionLaughsFailsFastWithAMessage) {
    std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
    for (int i = 1; i < 10; ++i) {
        text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
        for (int k = 0; k < 10; ++k) text += (k ? ", *a" : "*a") + std::to_string(i - 1);
        text += "]\n";
    }
    text += "vendor: *a9\n";
    const DeviceSource s = load_yaml(text);
    // 10 + 100 + 1000 + … : the alias on line 6 (a5, 10^6 nodes in total) crosses the limit.
    expect_error(s, "yaml-alias-expansion", 6, 45, "billion laughs");
}

TEST(YamlBadInput, ModestAliasReuseIsFine) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x6000: &input { name: In 1, type: UINT, access: ro, pdo: tx }
      0x6010: { name: In 2, type: UINT, access: ro, pdo: tx }
    txpdo:
      - { index: 0x1A00, entries: &entries [0x6000, 0x6010] }
      - { index: 0x1A01, assigned: false, entries: *entries }
)");
    EXPECT_TRUE(s.diagnostics.empty()) << describe(s.diagnostics);
    ASSERT_TRUE(s.document);
    EXPECT_EQ(esi::test::only_device(s).tx_pdos[1].entries.size(), 2u);
}

TEST(YamlBadInput, NestingAndSizeAreBounded) {
    expect_error(load_yaml("vendor: " + std::string(200, '[') + std::string(200, ']') + "\n"), "yaml-nesting-depth", 1, 72);
    DeviceSourceOptions small;
    small.max_bytes = 64;
    const DeviceSource s = load_yaml(header, "device.yaml", small);
    EXPECT_FALSE(s.document);
    ASSERT_EQ(s.diagnostics.size(), 1u);
    EXPECT_EQ(s.diagnostics.items()[0].rule, "yaml-too-large");
}

TEST(YamlBadInput, OneDocumentPerFile) {
    expect_error(load_yaml(header + "---\nvendor: {}\n"), "yaml-syntax", 9, 1, "one YAML document");
    expect_error(load_yaml(""), "yaml-missing-key", 1, 1, "empty");
    expect_error(load_yaml(std::string("vendor:\0x", 9)), "yaml-syntax", 1, 8, "NUL");
}

TEST(YamlBadInput, MissingKeysAreReportedAtTheMapping) {
    const DeviceSource s = load_yaml("vendor: { name: X }\ndevices:\n  - { type: D, name: D, product_code: 1, revision: 1 }\n");
    EXPECT_FALSE(s.document);
    EXPECT_NE(describe(s.diagnostics).find("1:9 error yaml-missing-key: vendor needs 'id'"), std::string::npos)
        << describe(s.diagnostics);
}

TEST(YamlBadInput, PdoEntryNamingAMissingObject) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x7000: { name: Out, type: USINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, entries: [0x7000, 0x7010] }
)");
    expect_error(s, "derive-pdo-entry-object", 12, 44, "0x7010, which is not in the object dictionary");
}

TEST(YamlBadInput, PdoEntryNamingAnUnknownNameSuggestsTheClosest) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x7000: { name: Output, type: USINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, entries: [Outptu] }
)");
    expect_error(s, "yaml-reference", 12, 36, "did you mean 'Output'?");
}

TEST(YamlBadInput, PdoEntryNamingANonMappableObject) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x7000: { name: Out, type: USINT, access: rw, pdo: tx }
    rxpdo:
      - { index: 0x1600, entries: [0x7000] }
)");
    expect_error(s, "derive-pdo-entry-mapping", 12, 36, "not mappable into RxPDOs");
}

TEST(YamlBadInput, ExplicitSmSizeSmallerThanItsPdos) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x7000: { name: Out, type: UDINT, access: rw, pdo: rx }
    rxpdo:
      - { index: 0x1600, entries: [0x7000] }
    sms:
      - { type: MBoxOut }
      - { type: MBoxIn }
      - { type: Outputs, size: 2 }
      - { type: Inputs }
)");
    expect_error(s, "derive-sm-size", 16, 32, "smaller than the 4 bytes of its default PDOs");
}

TEST(YamlBadInput, SmSizeContradictingTheMailboxSettings) {
    const DeviceSource s = load_yaml(header + "    sms:\n      - { type: MBoxOut, size: 64 }\n      - { type: MBoxIn }\n");
    expect_error(s, "derive-sm-size", 10, 32, "the mailbox settings say 128");
}

TEST(YamlBadInput, InitCmdValueThatDoesNotFitItsObject) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x6060: { name: Modes of operation, type: SINT, access: rw }
    init:
      - { transition: PS, object: 0x6060, value: 200 }
)");
    expect_error(s, "derive-init-value", 12, 50, "200 does not fit");
}

TEST(YamlBadInput, InitCmdValueForAMissingObjectAsksForData) {
    const DeviceSource s = load_yaml(header + "    init:\n      - { transition: PS, object: 0x6060, value: 3 }\n");
    expect_error(s, "derive-init-value", 10, 50, "give the bytes with 'data'");
}

TEST(YamlBadInput, InitCmdNeedsCoe) {
    const std::string no_coe = R"(vendor: { id: 0x10, name: Example }
devices:
  - { type: D, name: Device, product_code: 1, revision: 2, group: G, mailbox: { foe: true },
      init: [{ transition: PS, object: 0x6060, data: "03" }] }
)";
    expect_error(load_yaml(no_coe), "yaml-missing-key", 4, 7, "needs 'mailbox: {coe");
}

TEST(YamlBadInput, ValueAndDataAreOneHome) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x6060: { name: Mode, type: SINT, access: rw }
    init:
      - { transition: PS, object: 0x6060, value: 3, data: "03" }
)");
    expect_error(s, "yaml-conflict", 12, 53, "not both");
}

TEST(YamlBadInput, UnknownTransitionSuggests) {
    const DeviceSource s = load_yaml(header + "    init:\n      - { transition: SP0, object: 0x6060, data: \"03\" }\n");
    expect_error(s, "yaml-value", 10, 23, "did you mean 'SP'?");
}

TEST(YamlBadInput, UndeclaredDataType) {
    const DeviceSource s = load_yaml(header + "    objects:\n      0x2000: { name: Gain, type: DT_GAIN, bit_size: 32 }\n");
    expect_error(s, "derive-data-type", 10, 35, "'DT_GAIN' is neither a basic type");
}

TEST(YamlBadInput, UnknownLanguage) {
    const DeviceSource s = load_yaml(R"(vendor: { id: 0x10, name: { en: A, dee: B } }
devices: [{ type: D, name: D, product_code: 1, revision: 2, group: G }]
)");
    expect_error(s, "yaml-unknown-key", 1, 36, "did you mean 'de'?");
}

TEST(YamlBadInput, RecordNamedWithoutSubindex) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x6000:
        name: Inputs
        entries: { 1: { name: In 1, type: BOOL, access: ro, pdo: tx } }
    txpdo:
      - { index: 0x1A00, entries: [Inputs] }
)");
    expect_error(s, "yaml-reference", 14, 36, "is a record");
}

TEST(YamlBadInput, EnumTextThatIsNotAValue) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x8000: { name: Filter, type: USINT, access: rw, default: 5 ms, enum: { 0: 0 ms, 3: 3 ms } }
)");
    expect_error(s, "yaml-type", 10, 65, "not a number or a value of the enumeration");
}

TEST(YamlBadInput, DuplicateDeviceIdentity) {
    const DeviceSource s = load_yaml(R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - { type: A, name: A, product_code: 1, revision: 2 }
  - { type: B, name: B, product_code: 1, revision: 2 }
)");
    expect_error(s, "yaml-duplicate", 5, 5, "two devices have product code");
}

TEST(YamlBadInput, LimitsKeysAreCheckedLikeEveryOtherMapping) {
    const DeviceSource s = load_yaml(header + "    limits: { max_pdo: 4 }\n");
    expect_error(s, "yaml-unknown-key", 9, 15, "did you mean 'max_pdos'?");
}

TEST(YamlBadInput, HostileTextNeverThrows) {
    const char* inputs[] = {"[", "]", "{a: [}", "&a [*a]", "*unknown", "? [a]\n: b\n", "!!binary x", "\xff\xfe\x00",
                            "vendor: &v {id: 1, name: *v}\ndevices: []\n", "%YAML 9.9\n---\na: 1\n", "devices:\n  - *x\n",
                            "vendor: {id: 1, name: x}\ndevices:\n  - objects: {0x6000: {name: a, type: UINT, array: 300}}\n"};
    for (const char* text : inputs) {
        SCOPED_TRACE(text);
        DeviceSource s;
        EXPECT_NO_THROW(s = load_yaml(text));
        EXPECT_FALSE(s.document.has_value());
        EXPECT_TRUE(s.diagnostics.has_errors());
    }
}

TEST(YamlBadInput, LimitsPositionsAreTheFilesInBlockStyleToo) {
    const DeviceSource s = load_yaml(header + "    limits:\n      max_pdos: { rx: 4, tx: 4 }\n      bitlen: [8, 16, sixteen]\n"
                                              "    physics: YY\n");
    expect_error(s, "yaml-type", 11, 23, "bitlen");
}

TEST(YamlBadInput, LimitsAfterUnicodeTextKeepTheirColumns) {
    // The limits sit after "Größe" on the same line: columns count code points, not bytes.
    const DeviceSource s = load_yaml(
        "vendor: { id: 0x10, name: Example }\n"
        "devices: [{ type: D, name: Größe, product_code: 1, revision: 2, group: G, limits: { max_pdox: 1 } }]\n");
    expect_error(s, "yaml-unknown-key", 2, 85, "did you mean 'max_pdos'?");
}

TEST(YamlBadInput, EscapeHatchXmlMustBeWellFormed) {
    const DeviceSource s = load_yaml(header + "    xml: { elements: [\"<Info><Open></Info>\"] }\n");
    expect_error(s, "yaml-xml", 9, 23, "not well-formed XML");
}

// What pugixml lets through is refused too: it would be copied into the generated ESI file.
TEST(YamlBadInput, EscapeHatchXmlMeetsXmlOneDotZero) {
    const DeviceSource repeated = load_yaml(header + "    xml: { elements: [\"<Info A='1' A='1'/>\"] }\n");
    expect_error(repeated, "yaml-xml", 9, 23, "at character 13: attribute 'A' is given twice");
    const DeviceSource entity = load_yaml(header + "    xml: { elements: [\"<Info>&nbsp;</Info>\"] }\n");
    expect_error(entity, "yaml-xml", 9, 23, "undefined entity '&nbsp;'");
    const DeviceSource control = load_yaml(header + "    xml: { elements: [\"<Info>\\x01</Info>\"] }\n");
    expect_error(control, "yaml-xml", 9, 23, "U+0001");
}

TEST(YamlBadInput, PdoEntryDataTypeContradictingTheObject) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x6000: { name: In, type: INT, access: ro, pdo: tx }
    txpdo:
      - { index: 0x1A00, entries: [{ object: 0x6000, data_type: UINT }] }
)");
    expect_error(s, "derive-pdo-entry-type", 12, 65, "has data_type UINT, but In is INT");
}

TEST(YamlBadInput, PdoAssignedToAnSmTheDeviceDoesNotHave) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x6000: { name: In, type: INT, access: ro, pdo: tx }
    sms: [{ type: MBoxOut }, { type: MBoxIn }]
    txpdo:
      - { index: 0x1A00, entries: [0x6000] }
)");
    expect_error(s, "derive-pdo-assignment", 13, 9, "has no Inputs SM");
}

TEST(YamlBadInput, SyncManagerBeyondTheEscAddressSpace) {
    const DeviceSource s = load_yaml(header + "    sms:\n      - { type: MBoxOut }\n      - { type: MBoxIn, address: 0xFFC0 }\n");
    expect_error(s, "derive-sm-address", 11, 9, "beyond the 64 KiB");
}

TEST(YamlBadInput, OneImageOnly) {
    const DeviceSource s = load_yaml(header + "    image_file: a.bmp\n    image16x14: b.bmp\n");
    expect_error(s, "yaml-conflict", 4, 5, "one of image_data, image_file and image16x14");
}

TEST(YamlBadInput, EepromImageExcludesTheStructuredForm) {
    const DeviceSource s = load_yaml(header + "    eeprom: { data: 0011, size: 2048 }\n");
    expect_error(s, "yaml-conflict", 9, 27, "complete EEPROM image");
}

TEST(YamlBadInput, MissingFileIsAnIoError) {
    const DeviceSource s = load_device_source_file(esi::test::source_dir() / "samples" / "no-such-device.yaml");
    EXPECT_FALSE(s.document);
    ASSERT_EQ(s.diagnostics.size(), 1u);
    EXPECT_EQ(s.diagnostics.items()[0].rule, "io-error");
}

TEST(YamlBadInput, SwapDataIsTheSchemasEnumeration) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x6000: { name: In, type: DINT, access: ro, pdo: tx }
    txpdo:
      - { index: 0x1A00, entries: [{ object: 0x6000, swap_data: Swap_HB_LW }] }
)");
    expect_error(s, "yaml-value", 12, 65, "did you mean 'Swap_HB_LB'?");
}

// A misspelt data type (issue 14, item 8) is named at the type with the name meant, instead of
// surfacing as advice about default_data or a missing size.
namespace {

// The errors of `s` as "line:col message" lines.
std::string error_lines(const DeviceSource& s) {
    std::string out;
    for (const auto& d : s.diagnostics)
        if (d.severity == Severity::error) out += std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.message + "\n";
    return out;
}

}  // namespace

TEST(YamlTypeNames, AMisspeltTypeIsNamedWithTheTypeMeant) {
    const DeviceSource s = load_yaml(header + "    objects:\n      0x2000: { name: Setpoint, type: UNIT, access: rw, default: 0 }\n");
    EXPECT_FALSE(s.document);
    EXPECT_EQ(error_lines(s), "10:39 unknown type 'UNIT'; did you mean 'UINT'? (a basic type such as UINT, STRING(n), ARRAY [0..n] OF a "
                              "type, or a type declared in data_types)\n")
        << describe(s.diagnostics);
}

TEST(YamlTypeNames, NonStandardSpellingsAndRecordEntriesAndArrayElements) {
    const DeviceSource alias = load_yaml(header + "    objects:\n      0x2000: { name: Setpoint, type: UINT16, access: rw }\n");
    EXPECT_EQ(error_lines(alias).find("10:39 unknown type 'UINT16'; did you mean 'UINT'?"), 0u) << describe(alias.diagnostics);
    const DeviceSource entry = load_yaml(header + "    objects:\n      0x2001:\n        name: Gains\n        entries:\n          1: { name: Kp, type: RAEL }\n");
    EXPECT_EQ(error_lines(entry).find("13:32 unknown type 'RAEL'; did you mean 'REAL'?"), 0u) << describe(entry.diagnostics);
    EXPECT_EQ(entry.diagnostics.count(Severity::error), 1u) << "one error, no follow-up about the record: " << describe(entry.diagnostics);
    const DeviceSource array = load_yaml(header + "    objects:\n      0x2002: { name: Table, type: DITN, array: 4 }\n");
    EXPECT_NE(error_lines(array).find("unknown type 'DITN'; did you mean 'DINT'?"), std::string::npos) << describe(array.diagnostics);
}

TEST(YamlTypeNames, KnownAndDeclaredTypesAreAccepted) {
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x2000: { name: A, type: UINT, access: rw, default: 0 }
      0x2001: { name: B, type: STRING(8), access: ro }
      0x2002: { name: C, type: "ARRAY [0..3] OF BYTE", access: ro }
    data_types:
      - name: UINT1
        bit_size: 1
)");
    EXPECT_EQ(error_lines(s), "") << describe(s.diagnostics);
}

TEST(YamlTypeNames, ATypeDeclaredInTheSourceIsNotAMisspelling) {
    // UINT1 is close to UINT, but the source declares it (vendor files do).
    const DeviceSource s = load_yaml(header + R"(    objects:
      0x2000: { name: A, type: UINT1, access: ro }
    data_types:
      - name: UINT1
        bit_size: 1
)");
    EXPECT_EQ(error_lines(s).find("unknown type"), std::string::npos) << describe(s.diagnostics);
}
