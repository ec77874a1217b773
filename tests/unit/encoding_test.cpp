#include <gtest/gtest.h>

#include "esi/encoding.hpp"

using esi::decode_xml_bytes;
using esi::SourceEncoding;

TEST(Encoding, Utf8WithoutBomPassesThrough) {
    const auto d = decode_xml_bytes("<?xml version=\"1.0\"?><a>\xC3\xA4</a>");
    EXPECT_EQ(d.encoding, SourceEncoding::utf8);
    EXPECT_EQ(d.utf8, "<?xml version=\"1.0\"?><a>\xC3\xA4</a>");
    EXPECT_EQ(d.first_invalid_offset, std::string::npos);
}

TEST(Encoding, BomIsStripped) {
    const auto d = decode_xml_bytes("\xEF\xBB\xBF<a/>");
    EXPECT_EQ(d.encoding, SourceEncoding::utf8_bom);
    EXPECT_EQ(d.utf8, "<a/>");
}

TEST(Encoding, DeclaredLatin1BecomesUtf8) {
    const auto d = decode_xml_bytes("<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a>Schlie\xDF" "er \xE4</a>");
    EXPECT_EQ(d.encoding, SourceEncoding::latin1);
    EXPECT_EQ(d.utf8, "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a>Schlie\xC3\x9F" "er \xC3\xA4</a>");
}

TEST(Encoding, Iso8859WithoutDashIsRecognised) {
    const auto d = decode_xml_bytes("<?xml version='1.0' encoding='ISO8859-1'?><a>\xFC</a>");
    EXPECT_EQ(d.encoding, SourceEncoding::latin1);
    EXPECT_NE(d.utf8.find("\xC3\xBC"), std::string::npos);
}

TEST(Encoding, Windows1252QuotesAndEuro) {
    const auto d = decode_xml_bytes("<?xml version=\"1.0\" encoding=\"windows-1252\"?><a>\x80\x93</a>");
    EXPECT_EQ(d.encoding, SourceEncoding::windows1252);
    EXPECT_NE(d.utf8.find("\xE2\x82\xAC\xE2\x80\x9C"), std::string::npos);  // euro sign, left double quote
}

TEST(Encoding, Utf16LittleEndianWithBom) {
    const std::string bytes("\xFF\xFE<\0a\0/\0>\0\xE4\0", 12);
    const auto d = decode_xml_bytes(bytes);
    EXPECT_EQ(d.encoding, SourceEncoding::utf16le);
    EXPECT_EQ(d.utf8, "<a/>\xC3\xA4");
}

TEST(Encoding, Utf16BigEndianWithoutBom) {
    const std::string bytes("\0<\0?\0x\0m\0l", 10);
    const auto d = decode_xml_bytes(bytes);
    EXPECT_EQ(d.encoding, SourceEncoding::utf16be);
    EXPECT_EQ(d.utf8, "<?xml");
}

TEST(Encoding, LoneSurrogateIsReportedAndReplaced) {
    const std::string bytes("\xFF\xFE<\0\x00\xD8>\0", 8);
    const auto d = decode_xml_bytes(bytes);
    EXPECT_NE(d.first_invalid_offset, std::string::npos);
    EXPECT_EQ(d.utf8, "<\xEF\xBF\xBD>");
}

TEST(Encoding, InvalidUtf8IsReportedWithItsOffset) {
    const auto d = decode_xml_bytes("<a>ok\xDF" "er</a>");
    EXPECT_EQ(d.first_invalid_offset, 5u);
    EXPECT_TRUE(esi::is_valid_utf8(d.utf8));
}

TEST(Encoding, RejectsOverlongAndSurrogatesInUtf8) {
    EXPECT_FALSE(esi::is_valid_utf8("\xC0\xAF"));
    EXPECT_FALSE(esi::is_valid_utf8("\xED\xA0\x80"));
    EXPECT_FALSE(esi::is_valid_utf8("\xF4\x90\x80\x80"));
    EXPECT_TRUE(esi::is_valid_utf8("plain ascii that is longer than eight bytes \xF0\x9F\x98\x80"));
}

TEST(Encoding, OwnedDecodingGivesTheSameResultAsCopying) {
    for (const std::string& input : {std::string("\xEF\xBB\xBF<a>\xC3\xA4</a>"), std::string("<a>ok\xDF" "er</a>"),
                                    std::string("<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a>\xE4</a>"),
                                    std::string("\xFF\xFE<\0a\0/\0>\0", 10)}) {
        const auto copied = esi::decode_xml_bytes(input);
        const auto owned = esi::decode_xml_bytes_owned(input);
        EXPECT_EQ(copied.utf8, owned.utf8);
        EXPECT_EQ(copied.encoding, owned.encoding);
        EXPECT_EQ(copied.first_invalid_offset, owned.first_invalid_offset);
    }
}
