// A file of several devices: a token resolves within the device that holds it.

#include <gtest/gtest.h>

#include "navigate/navigate_test_support.hpp"

namespace esi::navigate {
namespace {

std::string device(const std::string& type, const std::string& object_name) {
    return "<Device><Type>" + type + "</Type><Name>" + type + " device</Name><Profile><Dictionary><DataTypes>"
           "<DataType><Name>DT6000</Name><BitSize>24</BitSize>"
           "<SubItem><SubIdx>0</SubIdx><Name>Count</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs></SubItem>"
           "<SubItem><SubIdx>1</SubIdx><Name>Value " + type + "</Name><Type>UINT</Type><BitSize>16</BitSize><BitOffs>8</BitOffs>"
           "<Flags><Access>ro</Access><PdoMapping>T</PdoMapping></Flags></SubItem></DataType></DataTypes><Objects>"
           "<Object><Index>#x6000</Index><Name>" + object_name + "</Name><Type>DT6000</Type><BitSize>24</BitSize>"
           "<Info><SubItem><Name>Value " + type + "</Name><Info><DefaultValue>7</DefaultValue></Info></SubItem></Info>"
           "</Object></Objects></Dictionary></Profile>\n"
           "<Sm StartAddress=\"#x1000\">Inputs</Sm>\n"
           "<TxPdo Sm=\"0\"><Index>#x1A00</Index><Name>In</Name>\n"
           "<Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>16</BitLen><Name>v</Name></Entry></TxPdo>\n"
           "<Dc><OpMode><Name>DC</Name><Sm No=\"0\"><Pdo>#x1A00</Pdo></Sm></OpMode></Dc>\n"
           "<Mailbox><CoE><InitCmd><Transition>PS</Transition><Index>#x6000</Index><SubIndex>1</SubIndex></InitCmd></CoE></Mailbox>\n"
           "</Device>\n";
}

class MultiDevice : public ::testing::Test {
protected:
    std::string text = "<EtherCATInfo><Descriptions><Devices>\n" + device("A", "First inputs") +
                       device("B", "Second inputs") + "</Devices></Descriptions></EtherCATInfo>\n";
    IndexPtr index = build_index(text, "two.xml");
};

TEST_F(MultiDevice, HoverResolvesInTheEnclosingDevice) {
    const auto first = hover(*index, test::at(text, "<Entry><Index>#x6000", 0, 15));
    const auto second = hover(*index, test::at(text, "<Entry><Index>#x6000", 1, 15));
    ASSERT_TRUE(first && second);
    EXPECT_EQ(first->markdown,
              "**#x6000:01 Value A**  \nsub-item of #x6000 First inputs\n\n- type: `UINT`\n- size: 16 bits\n"
              "- bit offset: 8\n- access: ro\n- PDO mapping: T\n- default: `7`\n");
    EXPECT_NE(second->markdown.find("sub-item of #x6000 Second inputs"), std::string::npos) << second->markdown;
}

TEST_F(MultiDevice, EntryOfASubItemGoesToTheSubItem) {
    const auto found = definition(*index, test::at(text, "<Entry><Index>#x6000", 1, 15));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, test::token_range(text, "<Name>Value B</Name><Type>", "Value B"));
}

TEST_F(MultiDevice, ReferencesStayInTheDevice) {
    const auto uses = references(*index, test::at(text, "<Object><Index>#x6000", 1, 16), true);
    ASSERT_EQ(uses.size(), 3u);  // the object, the PDO entry, the InitCmd of device B
    EXPECT_EQ(uses[0].range, test::token_range(text, "<Object><Index>#x6000", "#x6000", 1));
    EXPECT_EQ(uses[1].range, test::token_range(text, "<Entry><Index>#x6000", "#x6000", 1));
    EXPECT_EQ(uses[2].range, test::token_range(text, "<Transition>PS</Transition><Index>#x6000", "#x6000", 1));
}

TEST_F(MultiDevice, DcOpModePdoGoesToThePdo) {
    const auto found = definition(*index, test::at(text, "<Pdo>#x1A00", 1, 6));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, test::token_range(text, "<Index>#x1A00", "#x1A00", 1));
    const auto uses = references(*index, test::at(text, "<Index>#x1A00", 1, 8), false);
    ASSERT_EQ(uses.size(), 1u);
    EXPECT_EQ(uses[0].range, test::token_range(text, "<Pdo>#x1A00", "#x1A00", 1));
}

TEST_F(MultiDevice, OpModeSmNumberGoesToTheSm) {
    const auto found = definition(*index, test::at(text, "<Sm No=\"0\">", 0, 8));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].range, test::token_range(text, ">Inputs</Sm>", "Inputs", 0));
    const auto result = hover(*index, test::at(text, ">Inputs</Sm>", 1, 2));
    ASSERT_TRUE(result);
    EXPECT_EQ(result->markdown,
              "**SM0 Inputs** (process data inputs, device to master)\n\n- start address: #x1000\n"
              "- mapped by default: 16 bits (2 bytes)\n  - TxPdo #x1A00 In (16 bits)\n");
}

TEST(XmlTokens, CdataAndEntitiesKeepTheirTextRanges) {
    const std::string text = "<EtherCATInfo><Descriptions><Devices><Device><Type><![CDATA[A&B]]></Type>"
                             "<Profile><Dictionary><Objects><Object><Index> #x2000 </Index><Name>R&amp;D &#x3A9;&#937;</Name>"
                             "<Type>UINT</Type></Object></Objects></Dictionary></Profile></Device></Devices></Descriptions>"
                             "</EtherCATInfo>";
    const auto index = build_index(text, "t.xml");
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 1u);
    EXPECT_EQ(symbols[0].name, "A&B");
    EXPECT_EQ(symbols[0].selection_range, test::range_of(text, "A&B"));
    ASSERT_EQ(symbols[0].children.size(), 1u);
    // Blanks around a value are not part of the token; a name is shown with its references replaced.
    EXPECT_EQ(symbols[0].children[0].selection_range, test::range_of(text, "#x2000"));
    EXPECT_EQ(symbols[0].children[0].detail, "R&D \u03A9\u03A9");
}

TEST_F(MultiDevice, OutlineHasBothDevices) {
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 2u);
    EXPECT_EQ(symbols[0].name, "A");
    EXPECT_EQ(symbols[0].detail, "A device");
    EXPECT_EQ(symbols[1].name, "B");
    EXPECT_EQ(symbols[1].selection_range, test::token_range(text, "<Type>B</Type>", "B"));
    EXPECT_EQ(symbols[1].range.start, test::at(text, "<Device>", 1));
}

}  // namespace
}  // namespace esi::navigate
