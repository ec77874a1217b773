// Behaviour of the od-… rules and their helpers beyond the fixtures: how values are read, how
// type names resolve, and which Dictionaries are checked.

#include <gtest/gtest.h>

#include "check/od_type_index.hpp"
#include "check/od_values.hpp"
#include "rules/pdo_od_test_support.hpp"

namespace {

using esi::Number;
using esi::rules::ValueFormat;
using esi::test::findings_of;
using esi::test::lint_text;

esi::HexData hex(const std::string& text) { return esi::HexData{text, {}}; }

TEST(OdValues, DataIsLittleEndianAndSignExtendedByTheEntryWidth) {
    EXPECT_EQ(esi::rules::number_from_data(hex("001a"), ValueFormat{16, false}), Number::from_unsigned(0x1A00));
    EXPECT_EQ(esi::rules::number_from_data(hex("FFFF"), ValueFormat{16, true}), Number::from_signed(-1));
    EXPECT_EQ(esi::rules::number_from_data(hex("FFFF"), ValueFormat{16, false}), Number::from_unsigned(0xFFFF));
    // One byte for an INT is zero-extended: the sign bit is the entry's (bit 15), not the byte's.
    EXPECT_EQ(esi::rules::number_from_data(hex("80"), ValueFormat{16, true}), Number::from_unsigned(0x80));
    EXPECT_EQ(esi::rules::number_from_data(hex("0000000000000080"), ValueFormat{64, true}),
              (Number{std::uint64_t{1} << 63, true}));
    EXPECT_FALSE(esi::rules::number_from_data(hex("123"), ValueFormat{16, false}));  // odd length
    EXPECT_FALSE(esi::rules::number_from_data(hex("000000000000000000"), ValueFormat{64, false}));  // 9 bytes
}

TEST(OdValues, ValuesThatOnlyFitAsBitPatternsAreReadAsTwosComplement) {
    EXPECT_EQ(esi::rules::normalized(Number::from_unsigned(0xFFF80001), ValueFormat{32, true}), Number::from_signed(-524287));
    EXPECT_EQ(esi::rules::normalized(Number::from_unsigned(0x7FFFF), ValueFormat{32, true}), Number::from_unsigned(0x7FFFF));
    EXPECT_EQ(esi::rules::normalized(Number::from_signed(-1), ValueFormat{32, false}), Number::from_unsigned(0xFFFFFFFF));
    EXPECT_EQ(esi::rules::normalized(Number::from_signed(-5), ValueFormat{16, true}), Number::from_signed(-5));
    // Too wide for the entry in any reading: left as written.
    EXPECT_EQ(esi::rules::normalized(Number::from_unsigned(0x1FFFF), ValueFormat{16, true}), Number::from_unsigned(0x1FFFF));
}

TEST(OdValues, FormatLimitsAndOrdering) {
    EXPECT_EQ(esi::rules::format_min(ValueFormat{8, true}), Number::from_signed(-128));
    EXPECT_EQ(esi::rules::format_max(ValueFormat{8, true}), Number::from_unsigned(127));
    EXPECT_EQ(esi::rules::format_max(ValueFormat{64, false}), Number::from_unsigned(~std::uint64_t{0}));
    EXPECT_TRUE(esi::rules::less(Number::from_signed(-2), Number::from_signed(-1)));
    EXPECT_TRUE(esi::rules::less(Number::from_signed(-1), Number::from_unsigned(0)));
    EXPECT_FALSE(esi::rules::less(Number{0, true}, Number::from_unsigned(0)));  // -0 == 0
}

esi::Dictionary dictionary_with(std::vector<esi::DataType> types) {
    esi::Dictionary d;
    d.data_types = std::move(types);
    return d;
}

esi::DataType data_type(std::string name, std::optional<std::string> base, std::uint64_t bits) {
    esi::DataType t;
    t.name = std::move(name);
    t.base_type = std::move(base);
    t.bit_size = bits;
    return t;
}

TEST(OdTypeIndex, ArrayNamesResolveThroughTheirElementType) {
    const auto d = dictionary_with({data_type("DT_X", std::string("USINT"), 8)});
    const esi::rules::TypeIndex types(d);
    std::string_view culprit;
    EXPECT_EQ(types.status("ARRAY [0..3] OF UINT8", &culprit), esi::rules::TypeNameStatus::nonstandard);
    EXPECT_EQ(culprit, "UINT8");
    EXPECT_EQ(types.status("ARRAY [0..3] OF NOPE", &culprit), esi::rules::TypeNameStatus::unresolved);
    EXPECT_EQ(culprit, "NOPE");
    EXPECT_EQ(types.status("ARRAY [1..2] OF DT_X"), esi::rules::TypeNameStatus::resolved);
    EXPECT_EQ(types.bit_size("ARRAY [1..2] OF DT_X"), 16u);
    EXPECT_EQ(types.bit_size("STRING(10)"), 80u);
    EXPECT_EQ(types.bit_size("DT_UNKNOWN"), std::nullopt);
}

TEST(OdTypeIndex, CyclesAreFoundOnlyForTheirMembers) {
    const auto d = dictionary_with({data_type("A", std::string("B"), 16), data_type("B", std::string("A"), 16),
                                    data_type("C", std::string("A"), 16), data_type("UINT", std::string("UINT"), 16)});
    const esi::rules::TypeIndex types(d);
    EXPECT_TRUE(types.in_base_type_cycle(d.data_types[0]));
    EXPECT_TRUE(types.in_base_type_cycle(d.data_types[1]));
    EXPECT_FALSE(types.in_base_type_cycle(d.data_types[2])) << "C leads into the cycle but is not part of it";
    EXPECT_FALSE(types.in_base_type_cycle(d.data_types[3])) << "a basic type described by itself";
}

TEST(OdRules, ALoopOfManyDataTypesIsOneFindingAtItsFirstMember) {
    // DT1 -> DT2 -> ... -> DT500 -> DT1, declared in reverse order, plus a chain running into it.
    std::string types;
    for (int i = 500; i >= 1; --i)
        types += "<DataType><Name>DT" + std::to_string(i) + "</Name><BaseType>DT" + std::to_string(i == 500 ? 1 : i + 1) +
                 "</BaseType><BitSize>16</BitSize></DataType>\n";
    types += "<DataType><Name>DT_TAIL</Name><BaseType>DT7</BaseType><BitSize>16</BitSize></DataType>\n";
    const std::string xml = "<?xml version=\"1.0\"?>\n<EtherCATDict><Dictionary><DataTypes>\n" + types +
                            "</DataTypes><Objects/></Dictionary></EtherCATDict>\n";
    const auto found = findings_of(lint_text(xml), "od-type-cycle");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pos.line, 3u);  // DT500, the first member in the file
    EXPECT_EQ(found[0].message.rfind("DataType DT500 is its own base type through BaseType: DT500 -> DT1 -> DT2", 0), 0u)
        << found[0].message;
}

TEST(OdRules, EtherCATDictFilesAreChecked) {
    const std::string xml =
        "<?xml version=\"1.0\"?>\n"
        "<EtherCATDict>\n"
        "  <Dictionary>\n"
        "    <DataTypes><DataType><Name>UINT</Name><BitSize>16</BitSize></DataType></DataTypes>\n"
        "    <Objects>\n"
        "      <Object><Index>#x2000</Index><Name>A</Name><Type>UINT</Type><BitSize>16</BitSize></Object>\n"
        "      <Object><Index>#x2000</Index><Name>B</Name><Type>UINT16</Type><BitSize>16</BitSize></Object>\n"
        "    </Objects>\n"
        "  </Dictionary>\n"
        "</EtherCATDict>\n";
    const auto report = lint_text(xml);
    ASSERT_EQ(findings_of(report, "od-duplicate-object").size(), 1u);
    EXPECT_EQ(findings_of(report, "od-duplicate-object")[0].pos.line, 7u);
    EXPECT_EQ(findings_of(report, "od-nonstandard-type-name").size(), 1u);
    EXPECT_TRUE(findings_of(report, "od-mandatory-object").empty()) << "a dictionary file belongs to no CoE device";
}

TEST(OdRules, ModuleDictionariesAreChecked) {
    const std::string xml =
        "<?xml version=\"1.0\"?>\n"
        "<EtherCATModule><Vendor><Id>2</Id></Vendor><Modules><Module><Type ModuleIdent=\"#x1\">M</Type><Name>M</Name>\n"
        "<Profile><Dictionary><DataTypes/><Objects>\n"
        "<Object><Index>#x6000</Index><Name>In</Name><Type>DT6000</Type><BitSize>8</BitSize></Object>\n"
        "</Objects></Dictionary></Profile></Module></Modules></EtherCATModule>\n";
    const auto found = findings_of(lint_text(xml), "od-type-unresolved");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pos.line, 4u);
}

TEST(OdRules, DefaultRangeAcceptsEitherReadingOfAnAmbiguousValue) {
    // Inovance writes MaxValue 2147483648 for a DINT: as a bit pattern it is -2^31 (and the default
    // 0 would be above it), as a number 2^31 (and 0 is below it). Only a value out of range in both
    // readings is reported.
    const auto xml = [](const std::string& info) {
        return esi::test::one_device("        <Profile><Dictionary><DataTypes/><Objects>\n"
                                     "          <Object><Index>#x2000</Index><Name>P</Name><Type>DINT</Type><BitSize>32</BitSize>"
                                     "<Info>" + info + "</Info></Object>\n"
                                     "        </Objects></Dictionary></Profile>\n");
    };
    EXPECT_TRUE(findings_of(lint_text(xml("<MinValue>-2147483648</MinValue><MaxValue>2147483648</MaxValue><DefaultValue>0</DefaultValue>")),
                            "od-default-range").empty());
    const auto found = findings_of(lint_text(xml("<MinValue>-10</MinValue><MaxValue>10</MaxValue><DefaultValue>20</DefaultValue>")),
                                   "od-default-range");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].message, "the default 20 of #x2000 is above its MaxValue 10");
}

TEST(OdRules, DefaultDataOfTheWrongLengthIsOnlyALengthFinding) {
    // Synapticon writes MinData "80" for an INT meaning -128; the value is a guess, so only
    // od-default-length reports it.
    const std::string xml = esi::test::one_device(
        "        <Profile><Dictionary><DataTypes/><Objects>\n"
        "          <Object><Index>#x6086</Index><Name>P</Name><Type>INT</Type><BitSize>16</BitSize>"
        "<Info><MinData>80</MinData><MaxData>00</MaxData><DefaultData>80</DefaultData></Info></Object>\n"
        "        </Objects></Dictionary></Profile>\n");
    const auto report = lint_text(xml);
    EXPECT_EQ(findings_of(report, "od-default-length").size(), 3u);
    EXPECT_TRUE(findings_of(report, "od-default-range").empty());
}

}  // namespace
