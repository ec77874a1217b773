// The XML text emitter: repair of what XML cannot carry, layout, number spelling. The escaping
// itself is tested in unit/xml_text_test.cpp.

#include <gtest/gtest.h>

#include <pugixml.hpp>

#include "xml/writer_emitter.hpp"

namespace {

using esi::xml_writer::is_xml_name;
using esi::xml_writer::NumberText;
using esi::xml_writer::XmlEmitter;

TEST(Emitter, RecognisesXmlNames) {
    EXPECT_TRUE(is_xml_name("VendorSpecific"));
    EXPECT_TRUE(is_xml_name("xsi:noNamespaceSchemaLocation"));
    EXPECT_TRUE(is_xml_name("_a-b.c1"));
    EXPECT_FALSE(is_xml_name(""));
    EXPECT_FALSE(is_xml_name("1abc"));
    EXPECT_FALSE(is_xml_name("-abc"));
    EXPECT_FALSE(is_xml_name("a b"));
    EXPECT_FALSE(is_xml_name("a<b"));
}

TEST(Emitter, FormatsNumbers) {
    EXPECT_EQ(NumberText::hex(0x2, 8).view(), "#x00000002");
    EXPECT_EQ(NumberText::hex(0x1A00, 4).view(), "#x1A00");
    EXPECT_EQ(NumberText::hex(0x12345, 4).view(), "#x12345");  // minimum width, never truncated
    EXPECT_EQ(NumberText::hex(0, 0).view(), "#x0");
    EXPECT_EQ(NumberText::hex(UINT64_MAX, 4).view(), "#xFFFFFFFFFFFFFFFF");
    EXPECT_EQ(NumberText::decimal(std::uint64_t{18446744073709551615u}).view(), "18446744073709551615");
    EXPECT_EQ(NumberText::decimal(std::int64_t{INT64_MIN}).view(), "-9223372036854775808");
    EXPECT_EQ(NumberText::decimal(esi::Number{9223372036854775808u, true}).view(), "-9223372036854775808");
    EXPECT_EQ(NumberText::decimal(esi::Number{UINT64_MAX, false}).view(), "18446744073709551615");
    EXPECT_EQ(NumberText::decimal(esi::Number{0, true}).view(), "0");
    EXPECT_EQ(NumberText::decimal(esi::Number{5, true}).view(), "-5");
}

std::string emit(void (*body)(XmlEmitter&), std::string_view indent = "  ", std::string_view eol = "\n") {
    std::string out;
    XmlEmitter e(out, indent, eol);
    e.declaration();
    body(e);
    e.finish();
    return out;
}

TEST(Emitter, IndentsChildrenAndClosesEmptyElements) {
    const std::string out = emit([](XmlEmitter& e) {
        e.begin("Root");
        e.attribute("Version", "1.17");
        e.begin("Child");
        e.leaf("Leaf", "text");
        e.leaf("Empty", "");
        e.end();
        e.begin("Other");
        e.end();
        e.end();
    });
    EXPECT_EQ(out,
              "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<Root Version=\"1.17\">\n"
              "  <Child>\n"
              "    <Leaf>text</Leaf>\n"
              "    <Empty/>\n"
              "  </Child>\n"
              "  <Other/>\n"
              "</Root>\n");
}

TEST(Emitter, HonoursIndentAndLineEndingOptions) {
    const std::string out = emit(
        [](XmlEmitter& e) {
            e.begin("A");
            e.leaf("B", "x");
            e.end();
        },
        "\t", "\r\n");
    EXPECT_EQ(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\r\n<A>\r\n\t<B>x</B>\r\n</A>\r\n");
}

TEST(Emitter, WritesMixedContentWithoutAddingWhitespace) {
    const std::string out = emit([](XmlEmitter& e) {
        e.begin("Root");
        e.begin("Mixed");
        e.text("before ");
        e.begin("B");
        e.leaf("C", "deep");
        e.end();
        e.end();
        e.leaf("After", "x");
        e.end();
    });
    EXPECT_NE(out.find("  <Mixed>before <B><C>deep</C></B></Mixed>\n  <After>x</After>\n"), std::string::npos) << out;
}

TEST(Emitter, WritesARepeatedAttributeOnce) {
    const std::string out = emit([](XmlEmitter& e) {
        e.begin("A");
        e.attribute("x", "1");
        e.attribute("x", "2");
        e.end();
    });
    EXPECT_NE(out.find("<A x=\"1\"/>"), std::string::npos) << out;
}

TEST(Emitter, OutputOfHostileStringsIsWellFormed) {
    const std::string out = emit([](XmlEmitter& e) {
        e.begin("A");
        e.attribute("v", "\"'<&>\x01\xFF\r\n\t");
        e.text("]]><!-- <?pi?> &amp; \x02\xC3");
        e.end();
    });
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_buffer(out.data(), out.size(), pugi::parse_default, pugi::encoding_utf8)) << out;
    EXPECT_EQ(std::string(doc.child("A").attribute("v").value()), "\"'<&>\xEF\xBF\xBD\xEF\xBF\xBD\r\n\t");
    EXPECT_EQ(std::string(doc.child("A").text().get()), "]]><!-- <?pi?> &amp; \xEF\xBF\xBD\xEF\xBF\xBD");
}

}  // namespace
