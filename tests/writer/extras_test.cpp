// Unknown XML kept verbatim by the reader (Extras) goes back where it was: attributes after the
// typed ones, elements after the sibling named by `after`, or where the schema puts them.

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::device_file;
using esi::test::rewrite;

esi::XmlElement element(std::string name, std::string after, std::string text = {}) {
    esi::XmlElement e;
    e.name = std::move(name);
    e.after = std::move(after);
    e.text = std::move(text);
    return e;
}

// A device with the given extras and Type, two Names, GroupType and one Sm.
esi::EsiDocument device_with(std::vector<esi::XmlElement> extras) {
    esi::EsiDocument doc = esi::test::read_ok(device_file("<Type>T</Type><Name>A</Name><Name>B</Name><GroupType>IO</GroupType><Sm>x</Sm>"));
    doc.infos.at(0).devices.at(0).extras.elements = std::move(extras);
    return doc;
}

std::string device_xml(const esi::EsiDocument& doc) {
    const std::string out = esi::write_esi(doc);
    const auto from = out.find("<Device ");
    const auto to = out.find("</Device>");
    return out.substr(from, to - from);
}

TEST(WriterExtras, ElementGoesAfterTheSiblingItFollowed) {
    const std::string out = device_xml(device_with({element("Info", "Name", "i")}));
    EXPECT_TRUE(contains(out, "<Name>B</Name>\n        <Info>i</Info>\n        <GroupType>IO</GroupType>")) << out;
}

TEST(WriterExtras, ConsecutiveUnknownElementsStayTogetherInOrder) {
    const std::string out = device_xml(
        device_with({element("HideType", "Type", "h1"), element("HideType", "HideType", "h2"), element("AlternativeType", "HideType", "a")}));
    EXPECT_TRUE(contains(out, "<Type>T</Type>\n        <HideType>h1</HideType>\n        <HideType>h2</HideType>\n"
                              "        <AlternativeType>a</AlternativeType>\n        <Name>A</Name>"))
        << out;
}

TEST(WriterExtras, FirstChildStaysFirst) {
    const std::string out = device_xml(device_with({element("Sci", "", "s"), element("Unknown", "Sci", "u")}));
    EXPECT_TRUE(contains(out, "<Device Physics=\"YY\">\n        <Sci>s</Sci>\n        <Unknown>u</Unknown>\n        <Type>T</Type>")) << out;
}

TEST(WriterExtras, ElementWhoseAnchorIsGoneGoesToItsSchemaPlace) {
    // The source had <Comment/> before <Info/>; the model no longer has the comment.
    const std::string out = device_xml(device_with({element("Info", "Comment", "i"), element("ESC", "Dc", "e")}));
    EXPECT_TRUE(contains(out, "<Name>B</Name>\n        <Info>i</Info>\n        <GroupType>IO</GroupType>")) << out;
    // Dc (the anchor of ESC) is not written either: ESC goes after the SyncManagers, where the
    // schema allows it (before Eeprom and images), here at the end.
    EXPECT_TRUE(contains(out, "<Sm>x</Sm>\n        <ESC>e</ESC>\n      ")) << out;
}

TEST(WriterExtras, ElementWithoutAnchorButWithASchemaPlaceGoesThere) {
    // A generator that sets no `after` still gets a schema-valid position for known names.
    const std::string out = device_xml(device_with({element("Info", "", "i"), element("VendorSpecific", "", "v")}));
    EXPECT_TRUE(contains(out, "<Name>B</Name>\n        <Info>i</Info>\n        <GroupType>IO</GroupType>")) << out;
    EXPECT_TRUE(contains(out, "<Sm>x</Sm>\n        <VendorSpecific>v</VendorSpecific>\n")) << out;
}

TEST(WriterExtras, UnknownElementWithUnknownAnchorGoesLast) {
    const std::string out = device_xml(device_with({element("Mine", "Elsewhere", "m")}));
    EXPECT_TRUE(contains(out, "<Sm>x</Sm>\n        <Mine>m</Mine>\n      ")) << out;
}

TEST(WriterExtras, UnknownAttributesFollowTheTypedOnes) {
    esi::EsiDocument doc = device_with({});
    auto& device = doc.infos.at(0).devices.at(0);
    device.invisible = false;
    device.extras.attributes = {{"Crc32", "#x12"}, {"Physics", "ignored: typed attribute wins"}, {"bad name", "dropped"}};
    const std::string out = device_xml(doc);
    EXPECT_EQ(out.substr(0, out.find('>') + 1), R"(<Device Physics="YY" Invisible="false" Crc32="#x12">)");
}

TEST(WriterExtras, VerbatimTreesKeepAttributesTextAndNesting) {
    const std::string body = R"(<Type>T</Type><Name>A</Name>
        <Info>
          <Electrical><EBusCurrent>-100</EBusCurrent></Electrical>
          <StateMachine><Timeout><PreopTimeout>2000</PreopTimeout></Timeout><Behavior StartToSafeop="1"/></StateMachine>
          <Port><Type>MII</Type><Label>IN &amp; "out"</Label></Port>
        </Info>
        <GroupType>IO</GroupType>)";
    const std::string out = rewrite(device_file(body));
    EXPECT_TRUE(contains(out,
                         "        <Info>\n"
                         "          <Electrical>\n"
                         "            <EBusCurrent>-100</EBusCurrent>\n"
                         "          </Electrical>\n"
                         "          <StateMachine>\n"
                         "            <Timeout>\n"
                         "              <PreopTimeout>2000</PreopTimeout>\n"
                         "            </Timeout>\n"
                         "            <Behavior StartToSafeop=\"1\"/>\n"
                         "          </StateMachine>\n"
                         "          <Port>\n"
                         "            <Type>MII</Type>\n"
                         "            <Label>IN &amp; \"out\"</Label>\n"
                         "          </Port>\n"
                         "        </Info>\n"))
        << out;
}

TEST(WriterExtras, VerbatimTextIsWrittenAsReadIncludingMixedContent) {
    const std::string body = R"(<Type>T</Type><Name>A</Name><GroupType>IO</GroupType>
        <VendorSpecific><Note>  spaced  </Note><Para>Hello <b>bold</b> world</Para><Cr>a&#13;b</Cr></VendorSpecific>)";
    const std::string out = rewrite(device_file(body));
    EXPECT_TRUE(contains(out, "<Note>  spaced  </Note>")) << out;
    // The reader keeps the text of mixed content but not where it stood among the children: it
    // is written first, and nothing is added around the children.
    EXPECT_TRUE(contains(out, "<Para>Hello  world<b>bold</b></Para>")) << out;
    EXPECT_TRUE(contains(out, "<Cr>a&#13;b</Cr>")) << out;
    const auto doc = esi::test::read_ok(out);
    const auto* para = doc.infos.at(0).devices.at(0).extras.find("VendorSpecific/Para");
    ASSERT_NE(para, nullptr);
    EXPECT_EQ(para->text, "Hello  world");
    EXPECT_EQ(para->child("b")->text, "bold");
    EXPECT_EQ(doc.infos[0].devices[0].extras.find("VendorSpecific/Cr")->text, "a\rb");
}

TEST(WriterExtras, TextOfTypedSimpleElementsKeepsUnknownChildren) {
    const std::string out = rewrite(device_file(R"(<Type ProductCode="1">T<Extra/></Type><Name>A</Name><GroupType>IO</GroupType>)"));
    EXPECT_TRUE(contains(out, R"(<Type ProductCode="#x00000001">T<Extra/></Type>)")) << out;
}

TEST(WriterExtras, ElementsWithNamesXmlCannotCarryAreLeftOut) {
    esi::EsiDocument doc = device_with({element("not a name", "Name"), element("Good", "Name")});
    const std::string out = esi::write_esi(doc);
    EXPECT_FALSE(contains(out, "not a name"));
    EXPECT_TRUE(contains(out, "<Good/>"));
    EXPECT_TRUE(esi::read_esi(out, "t.xml").document.has_value());
}

TEST(WriterExtras, AbsurdlyDeepVerbatimTreesAreCutNotFollowedIntoAStackOverflow) {
    esi::XmlElement root = element("Deep", "Name");
    esi::XmlElement* at = &root;
    for (int i = 0; i < 5000; ++i) {
        at->children.push_back(element("Level", ""));
        at = &at->children.back();
    }
    at->text = "bottom";
    // Moved, not copied: a copy of the tree recurses 5000 levels in the test itself, whose stack
    // use depends on the compiler (clang -O0 under ASan overflows 8 MB).
    std::vector<esi::XmlElement> extras;
    extras.push_back(std::move(root));
    const std::string out = esi::write_esi(device_with(std::move(extras)));
    EXPECT_TRUE(esi::read_esi(out, "deep.xml").document.has_value());
    EXPECT_FALSE(contains(out, "bottom"));
    std::size_t levels = 0;
    for (auto at_level = out.find("<Level"); at_level != std::string::npos; at_level = out.find("<Level", at_level + 1)) ++levels;
    EXPECT_EQ(levels, 1024u);  // the writer's depth limit
}

TEST(WriterExtras, InfoListAndDictRootExtrasArePlaced) {
    const std::string dict = R"(<EtherCATDict><Before/><Dictionary><Objects/></Dictionary><After/></EtherCATDict>)";
    const std::string out = rewrite(dict);
    EXPECT_TRUE(contains(out, "<EtherCATDict>\n  <Before/>\n  <Dictionary>\n    <Objects/>\n  </Dictionary>\n  <After/>\n</EtherCATDict>\n")) << out;
}

}  // namespace
