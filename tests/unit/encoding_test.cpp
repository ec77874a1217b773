#include <gtest/gtest.h>

#include "esi/encoding.hpp"
#include "esi/source_text.hpp"

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

TEST(SourceText, PositionsCountCodePointsAndLines) {
    const std::string text = "ab\n\xC3\xA4\xC3\xB6x\r\n\n" + std::string(40, 'y') + "\xE2\x82\xAC" + "z";
    esi::SourceText source("t.xml", text);
    EXPECT_EQ(source.position_of(0), (esi::SourcePos{1, 1}));
    EXPECT_EQ(source.position_of(7), (esi::SourcePos{2, 3}));  // 'x' after two 2-byte letters
    EXPECT_EQ(source.position_of(text.size() - 1), (esi::SourcePos{4, 42}));
    esi::PositionCursor cursor(source);
    for (std::size_t offset : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{11}, text.size() - 1, std::size_t{3}})
        EXPECT_EQ(cursor.position_of(offset), source.position_of(offset)) << offset;
    EXPECT_EQ(source.line(2), "\xC3\xA4\xC3\xB6x");
    EXPECT_EQ(esi::count_newlines(text), 3u);
    EXPECT_EQ(esi::count_code_points("\xE2\x82\xAC" "abcdefghijk\xC3\xA4"), 13u);
}

TEST(SourceText, CodePointsOfEverySpanAgreeWithAByteCount) {
    // Every span of a text mixing 1- to 4-byte characters, so that the eight-byte blocks and the
    // masked last load start and end inside characters and at every distance from the text's start.
    std::string text;
    const std::string pieces[] = {"a", "\xC3\xA4", "\xE2\x82\xAC", "\xF0\x9F\x98\x80", "bcdefghij", "\t"};
    for (int i = 0; i < 40; ++i) text += pieces[(i * 5 + i / 4) % 6];
    for (std::size_t begin = 0; begin < text.size(); ++begin) {
        for (std::size_t length = 0; begin + length <= text.size(); ++length) {
            const std::string_view span = std::string_view(text).substr(begin, length);
            std::size_t expected = 0;
            for (const char c : span) expected += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
            ASSERT_EQ(esi::count_code_points(span), expected) << begin << "+" << length;
        }
    }
}

TEST(SourceText, CursorAgreesWithTheLineIndexAtEveryOffset) {
    // Lines of mixed length with CRLF, 2-, 3- and 4-byte characters at word boundaries, a
    // newline as the last byte and runs longer than one 8-byte word without any newline.
    std::string text;
    const std::string pieces[] = {"<a>", "\r\n", "\xC3\xA4", "\xE2\x82\xAC", "\xF0\x9F\x98\x80", "\n", "abcdefghijklmnopq", "\t\t"};
    for (int i = 0; i < 400; ++i) text += pieces[(i * 7 + i / 3) % 8];
    text += "\n";
    esi::SourceText source("t.xml", text);
    for (std::size_t step : {std::size_t{1}, std::size_t{3}, std::size_t{8}, std::size_t{13}, std::size_t{64}}) {
        esi::PositionCursor cursor(source);
        for (std::size_t offset = 0; offset <= text.size(); offset += step)
            ASSERT_EQ(cursor.position_of(offset), source.position_of(offset)) << "offset " << offset << " step " << step;
    }
    esi::PositionCursor cursor(source);
    EXPECT_EQ(cursor.position_of(text.size() + 10), source.position_of(text.size()));  // clamped to the end
    EXPECT_EQ(cursor.position_of(5), source.position_of(5));                            // backwards
}
