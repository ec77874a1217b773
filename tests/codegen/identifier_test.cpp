// C identifiers and literals made from EtherCAT names.

#include <gtest/gtest.h>

#include "esi/codegen/identifier.hpp"

using esi::codegen::c_comment_text;
using esi::codegen::c_identifier;
using esi::codegen::c_macro_name;
using esi::codegen::c_string_literal;
using esi::codegen::IdentifierScope;

TEST(CIdentifier, NamesBecomeLowerSnakeCase) {
    EXPECT_EQ(c_identifier("Modes of operation"), "modes_of_operation");
    EXPECT_EQ(c_identifier("  TxPDO-Map (Ch.1)  "), "txpdo_map_ch_1");
    EXPECT_EQ(c_identifier("SubIndex 001"), "subindex_001");
}

TEST(CIdentifier, GermanLettersAreTransliterated) {
    EXPECT_EQ(c_identifier("Übertemperatur Größe"), "uebertemperatur_groesse");
}

TEST(CIdentifier, LeadingDigitGetsAPrefix) { EXPECT_EQ(c_identifier("3 phase currents"), "n_3_phase_currents"); }

TEST(CIdentifier, KeywordsGetATrailingUnderscore) {
    EXPECT_EQ(c_identifier("Default"), "default_");
    EXPECT_EQ(c_identifier("register"), "register_");
    EXPECT_EQ(c_identifier("errno"), "errno_");
}

TEST(CIdentifier, EmptyNamesUseTheFallback) {
    EXPECT_EQ(c_identifier("", "object_6000"), "object_6000");
    EXPECT_EQ(c_identifier("---", "x"), "x");
    EXPECT_EQ(c_identifier("", ""), "unnamed");
}

TEST(CIdentifier, NeverReservedUnderscores) {
    const std::string id = c_identifier("__Weird__ name__");
    EXPECT_EQ(id, "weird_name");
    EXPECT_EQ(id.find("__"), std::string::npos);
}

TEST(CIdentifier, MacroNamesAreUpperCase) {
    EXPECT_EQ(c_macro_name("EX-DIO-8"), "EX_DIO_8");
    EXPECT_EQ(c_macro_name("default"), "DEFAULT");
}

TEST(IdentifierScope, DuplicatesTakeTheDisambiguatorThenACounter) {
    IdentifierScope scope;
    EXPECT_EQ(scope.claim("status", "6000"), "status");
    EXPECT_EQ(scope.claim("status", "6010"), "status_6010");
    EXPECT_EQ(scope.claim("status", "6010"), "status_2");
    EXPECT_EQ(scope.claim("status"), "status_3");
}

TEST(IdentifierScope, ReservedNamesAreNotHandedOut) {
    IdentifierScope scope;
    scope.reserve("entries");
    EXPECT_EQ(scope.claim("entries"), "entries_2");
}

TEST(CStringLiteral, EscapesQuotesBackslashesTrigraphsAndBytes) {
    EXPECT_EQ(c_string_literal("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(c_string_literal("?" "?="), "\"\\?\\?=\"");  // "?" "?=": no trigraph in this file
    // Octal escapes are three digits, so a following digit cannot join them.
    EXPECT_EQ(c_string_literal(std::string("\x01" "1", 2)), "\"\\0011\"");
    EXPECT_EQ(c_string_literal("\xC3\x9C"), "\"\\303\\234\"");
    EXPECT_EQ(c_string_literal(std::string(1, '\0')), "\"\\000\"");
}

TEST(CCommentText, CannotCloseTheCommentOrFormTrigraphs) {
    const std::string text = c_comment_text("a */ b ?" "?/\nc /* d");
    EXPECT_EQ(text.find("*/"), std::string::npos);
    EXPECT_EQ(text.find("??"), std::string::npos);
    EXPECT_EQ(text.find("/*"), std::string::npos);
    EXPECT_EQ(text.find('\n'), std::string::npos);
}
