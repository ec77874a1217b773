#include <gtest/gtest.h>

#include "esi/number.hpp"

using esi::NumberError;
using esi::NumberSyntax;
using esi::parse_number;

TEST(Number, ReadsDecimalAndHashHex) {
    EXPECT_EQ(parse_number("16").value.magnitude, 16u);
    EXPECT_EQ(parse_number("#x10").value.magnitude, 16u);
    EXPECT_EQ(parse_number("#x10").syntax, NumberSyntax::hash_hex);
    EXPECT_EQ(parse_number("#xabcDEF").value.magnitude, 0xABCDEFu);
}

TEST(Number, TrimsSurroundingWhitespace) { EXPECT_EQ(parse_number("  \r\n #x264860d2 \t").value.magnitude, 0x264860D2u); }

TEST(Number, AcceptsCPrefixButSaysSo) {
    const auto n = parse_number("0xF3F");
    ASSERT_TRUE(n.ok());
    EXPECT_EQ(n.value.magnitude, 0xF3Fu);
    EXPECT_EQ(n.syntax, NumberSyntax::c_hex);
}

TEST(Number, NegativeValues) {
    const auto n = parse_number("-2147483648");
    ASSERT_TRUE(n.ok());
    EXPECT_EQ(n.value.as_int64(), -2147483648LL);
    EXPECT_TRUE(n.value.fits_signed_bits(32));
    EXPECT_FALSE(esi::Number::from_signed(2147483648LL).fits_signed_bits(32));
    EXPECT_EQ(parse_number("-#x10").value.as_int64(), -16);
}

TEST(Number, FullUnsigned64BitRange) {
    const auto n = parse_number("#xFFFFFFFFFFFFFFFF");
    ASSERT_TRUE(n.ok());
    EXPECT_EQ(n.value.as_uint64(), 0xFFFFFFFFFFFFFFFFull);
    EXPECT_FALSE(n.value.as_int64().has_value());
    EXPECT_TRUE(n.value.fits_unsigned_bits(64));
    EXPECT_EQ(parse_number("18446744073709551615").value.as_uint64(), 0xFFFFFFFFFFFFFFFFull);  // the last decimal digit may be 5
    EXPECT_EQ(parse_number("18446744073709551620").error, NumberError::overflow);
    EXPECT_EQ(parse_number("184467440737095516150").error, NumberError::overflow);
}

TEST(Number, TrimsXmlWhiteSpaceOnly) {
    EXPECT_EQ(esi::trim(" \t\r\n#x10\r\n"), "#x10");
    EXPECT_EQ(esi::trim("\v1\f"), "\v1\f");  // vertical tab and form feed are not XML white space
    EXPECT_EQ(esi::trim("\xA0" "1"), "\xA0" "1");
    EXPECT_EQ(esi::trim(" \t "), "");
    EXPECT_EQ(parse_number(" 42\t").value.as_uint64(), 42u);
}

TEST(Number, RejectsMalformed) {
    EXPECT_EQ(parse_number("").error, NumberError::empty);
    EXPECT_EQ(parse_number("#x").error, NumberError::no_digits);
    EXPECT_EQ(parse_number("#x0x607F").error, NumberError::bad_digit);
    EXPECT_EQ(parse_number("12h").error, NumberError::bad_digit);
    EXPECT_EQ(parse_number("18446744073709551616").error, NumberError::overflow);
    EXPECT_EQ(parse_number("#x10000000000000000").error, NumberError::overflow);
}

TEST(Number, FormatsEsiHex) {
    EXPECT_EQ(esi::format_hex(0x1600, 4), "#x1600");
    EXPECT_EQ(esi::format_hex(0x2, 8), "#x00000002");
    EXPECT_EQ(esi::format_hex(0), "#x0");
    EXPECT_EQ(esi::format_decimal(esi::Number::from_signed(-5)), "-5");
}

TEST(Number, BooleansAreTrueFalseOneZero) {
    EXPECT_EQ(esi::parse_boolean("true"), true);
    EXPECT_EQ(esi::parse_boolean(" 1 "), true);
    EXPECT_EQ(esi::parse_boolean("false"), false);
    EXPECT_EQ(esi::parse_boolean("0"), false);
    EXPECT_FALSE(esi::parse_boolean("yes"));
    EXPECT_FALSE(esi::parse_boolean("TRUE"));
}
