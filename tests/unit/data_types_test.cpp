#include <gtest/gtest.h>

#include <set>

#include "esi/data_types.hpp"

TEST(DataTypes, BasicTypesHaveCoeCodesAndSizes) {
    const auto* uint = esi::find_basic_type("UINT");
    ASSERT_NE(uint, nullptr);
    EXPECT_EQ(uint->coe_code, 0x0006);
    EXPECT_EQ(uint->bit_size, 16u);
    EXPECT_FALSE(uint->is_signed());
    const auto* dint = esi::find_basic_type("DINT");
    ASSERT_NE(dint, nullptr);
    EXPECT_EQ(dint->coe_code, 0x0004);
    EXPECT_TRUE(dint->is_signed());
    EXPECT_EQ(esi::find_basic_type("ULINT")->coe_code, 0x001B);
    EXPECT_EQ(esi::find_basic_type("INT24")->bit_size, 24u);
    EXPECT_EQ(esi::find_basic_type("BIT3")->coe_code, 0x0032);
    EXPECT_EQ(esi::find_basic_type("BITARR16")->bit_size, 16u);
    EXPECT_EQ(esi::find_basic_type("BOOL")->bit_size, 1u);
}

TEST(DataTypes, LookupByCodeAndCoeName) {
    EXPECT_EQ(esi::find_basic_type_by_code(0x0007)->esi_name, "UDINT");
    EXPECT_EQ(esi::find_basic_type_by_coe_name("UNSIGNED16")->esi_name, "UINT");
    EXPECT_EQ(esi::find_basic_type_by_code(0x0017), nullptr);
}

TEST(DataTypes, EveryCodeAndNameIsUnique) {
    std::set<std::uint16_t> codes;
    std::set<std::string_view> names;
    for (const auto& t : esi::basic_types()) {
        EXPECT_TRUE(codes.insert(t.coe_code).second) << t.esi_name;
        EXPECT_TRUE(names.insert(t.esi_name).second) << t.esi_name;
    }
}

TEST(DataTypes, ParsesStringAndArrayNames) {
    const auto s = esi::parse_type_name("STRING(10)");
    EXPECT_EQ(s.kind, esi::TypeName::Kind::string);
    EXPECT_EQ(s.string_length, 10u);
    const auto a = esi::parse_type_name("ARRAY [0..3] OF BYTE");
    EXPECT_EQ(a.kind, esi::TypeName::Kind::array);
    EXPECT_EQ(a.element_count(), 4u);
    EXPECT_EQ(a.element, "BYTE");
    EXPECT_EQ(esi::parse_type_name("DT1018").kind, esi::TypeName::Kind::named);
}

TEST(DataTypes, ImpliedBitSizes) {
    EXPECT_EQ(esi::implied_bit_size("STRING(6)"), 48u);
    EXPECT_EQ(esi::implied_bit_size("ARRAY [0..19] OF BYTE"), 160u);
    EXPECT_EQ(esi::implied_bit_size("ARRAY [1..2] OF UINT"), 32u);
    EXPECT_EQ(esi::implied_bit_size("LREAL"), 64u);
    EXPECT_FALSE(esi::implied_bit_size("DT1C12").has_value());
}

TEST(DataTypes, SuggestsStandardNamesForCommonMistakes) {
    EXPECT_EQ(esi::standard_type_name_for("UINT16"), "UINT");
    EXPECT_EQ(esi::standard_type_name_for("UINT8"), "USINT");
    EXPECT_EQ(esi::standard_type_name_for("UNSIGNED32"), "UDINT");
    EXPECT_EQ(esi::standard_type_name_for("UINT"), "");
}

TEST(DataTypes, CanonicalNamesIgnoreSpacing) {
    EXPECT_EQ(esi::canonical_type_name("ARRAY[0..3]  OF BYTE"), "ARRAY [0..3] OF BYTE");
    EXPECT_EQ(esi::canonical_type_name(" UINT "), "UINT");
}
