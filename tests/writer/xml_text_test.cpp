// Strings XML 1.0 cannot carry (C0 controls, invalid UTF-8) in any text of the model: the ESI
// writer replaces them with U+FFFD (esi/xml_text.hpp), so the file is well-formed for a strict
// parser (xmllint) and reads back with the replacement character.

#include "writer/writer_test_support.hpp"

namespace {

constexpr std::string_view replacement = "\xEF\xBF\xBD";  // U+FFFD

// A vendor Name, a vendor attribute and an unknown element's text and attribute, each with a
// C0 control and an invalid UTF-8 byte.
esi::EsiDocument hostile_document() {
    esi::EsiDocument doc = esi::test::read_ok(esi::test::device_file("<Type>T</Type><Name>N</Name>"));
    esi::Vendor& vendor = *doc.infos.at(0).vendor;
    vendor.names.at(0).text = "V\x01" "endor\xFF";
    vendor.extras.attributes.push_back({"Note", "a\x02" "b\xC3"});
    esi::XmlElement element;
    element.name = "Remark";
    element.attributes.push_back({"x", "\x1F\xED\xA0\x80"});
    element.text = "t\x0B" "ext\xC0\xAF";
    vendor.extras.elements.push_back(element);
    return doc;
}

}  // namespace

TEST(WriterXmlText, ControlCharactersAndInvalidUtf8BecomeReplacementCharacters) {
    const std::string out = esi::write_esi(hostile_document());
    for (const char c : out) {
        const auto u = static_cast<unsigned char>(c);
        EXPECT_FALSE(u < 0x20 && u != '\t' && u != '\n' && u != '\r') << "C0 control " << int{u} << " in\n" << out;
    }
    const esi::ReadResult back = esi::read_esi(out, "back.xml");
    ASSERT_TRUE(back.document);
    EXPECT_TRUE(back.diagnostics.empty()) << back.diagnostics.items()[0].message;  // no xml-encoding: valid UTF-8
    const esi::Vendor& vendor = *back.document->infos.at(0).vendor;
    const std::string r(replacement);
    EXPECT_EQ(vendor.names.at(0).text, "V" + r + "endor" + r);
    ASSERT_EQ(vendor.extras.attributes.size(), 1u);
    EXPECT_EQ(vendor.extras.attributes[0].value, "a" + r + "b" + r);
    ASSERT_EQ(vendor.extras.elements.size(), 1u);
    EXPECT_EQ(vendor.extras.elements[0].attributes.at(0).value, r + r + r + r);  // one per byte of the surrogate
    EXPECT_EQ(vendor.extras.elements[0].text, "t" + r + "ext" + r + r);
}

TEST(WriterXmlText, AStrictXmlParserAcceptsTheOutput) {
    const std::string out = esi::write_esi(hostile_document());
    if (esi::test::run({"sh", "-c", "command -v xmllint"}).exit_code != 0) GTEST_SKIP() << "xmllint not installed";
    const esi::test::RunResult lint = esi::test::run({"xmllint", "--noout", "-"}, out);
    EXPECT_EQ(lint.exit_code, 0) << lint.err << out;
}
