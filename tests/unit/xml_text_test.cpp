// The one XML text escaper (esi/xml_text.hpp) of the ESI writer and the YAML import: markup,
// layout characters, and what XML 1.0 cannot carry (C0 controls, invalid UTF-8, U+FFFE/U+FFFF).

#include <gtest/gtest.h>

#include <string>

#include "esi/xml_text.hpp"

namespace {

std::string escaped(std::string_view text, bool attribute) {
    return esi::xml_escaped(text, attribute ? esi::XmlTextKind::attribute_value : esi::XmlTextKind::character_data);
}

TEST(XmlText, EscapesMarkupInText) {
    EXPECT_EQ(escaped("a & b < c > d \"q\" 'x'", false), "a &amp; b &lt; c &gt; d \"q\" 'x'");
    EXPECT_EQ(escaped("]]>", false), "]]&gt;");
}

TEST(XmlText, EscapesQuotesAndLayoutCharactersInAttributes) {
    EXPECT_EQ(escaped("say \"hi\" & <go>", true), "say &quot;hi&quot; &amp; &lt;go&gt;");
    // Attribute-value normalisation would turn these into spaces.
    EXPECT_EQ(escaped("a\tb\nc\rd", true), "a&#9;b&#10;c&#13;d");
}

TEST(XmlText, KeepsTabAndNewlineInTextButProtectsCarriageReturn) {
    EXPECT_EQ(escaped("line 1\n\tline 2\r\n", false), "line 1\n\tline 2&#13;\n");
}

TEST(XmlText, ReplacesControlCharactersXmlCannotCarry) {
    EXPECT_EQ(escaped(std::string("a\x01" "b\x1F" "c", 5), false), "a\xEF\xBF\xBD" "b\xEF\xBF\xBD" "c");
    EXPECT_EQ(escaped(std::string("a\0b", 3), true), "a\xEF\xBF\xBD" "b");
}

TEST(XmlText, KeepsValidUtf8) {
    const std::string text = "Gr\xC3\xB6\xC3\x9F" "e \xE2\x82\xAC \xF0\x9F\x94\x8C \xE4\xB8\xAD";  // Größe € 🔌 中
    EXPECT_EQ(escaped(text, false), text);
    EXPECT_EQ(escaped(text, true), text);
}

TEST(XmlText, ReplacesInvalidUtf8) {
    EXPECT_EQ(escaped("\xFF", false), "\xEF\xBF\xBD");                     // not a lead byte
    EXPECT_EQ(escaped("a\xC3", false), "a\xEF\xBF\xBD");                   // truncated sequence
    EXPECT_EQ(escaped("\xC0\xAF", false), "\xEF\xBF\xBD\xEF\xBF\xBD");     // overlong '/'
    EXPECT_EQ(escaped("\xED\xA0\x80", false), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // surrogate
    EXPECT_EQ(escaped("\xF4\x90\x80\x80", false).substr(0, 3), "\xEF\xBF\xBD");         // above U+10FFFF
    EXPECT_EQ(escaped("\xEF\xBF\xBE", false).substr(0, 3), "\xEF\xBF\xBD");             // U+FFFE
    // ISO-8859-1 text that was never decoded: each stray byte is replaced, the rest kept.
    EXPECT_EQ(escaped("Gr\xF6\xDF" "e", false), "Gr\xEF\xBF\xBD\xEF\xBF\xBD" "e");
}

TEST(XmlText, AppendsToWhatIsThere) {
    std::string out = "<A>";
    esi::append_xml_escaped(out, "x\x01", esi::XmlTextKind::character_data);
    EXPECT_EQ(out, "<A>x\xEF\xBF\xBD");
}

TEST(XmlText, KeepsDelAndC1ControlsWhichXml10Allows) {
    const std::string text = "a\x7F" "b\xC2\x85" "c";  // U+007F, U+0085 (NEL)
    EXPECT_EQ(escaped(text, false), text);
}

}  // namespace
