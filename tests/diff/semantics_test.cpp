// What is not a change: the differ compares models, so spelling, formatting and the order of
// elements whose order ETG gives no meaning must not show up, while the order that is the
// process-image layout must.

#include <algorithm>

#include <gtest/gtest.h>

#include "diff_fixture.hpp"
#include "esi/encoding.hpp"

namespace {

using esi::ChangeKind;
using esi::test::diff_base;
using esi::test::diff_texts;
using esi::test::edit;

void expect_identical(const std::string& old_xml, const std::string& new_xml) {
    const esi::DiffResult r = diff_texts(old_xml, new_xml);
    EXPECT_TRUE(r.identical()) << esi::test::describe(r);
    EXPECT_EQ(r.verdict, esi::Verdict::identical);
}

// Moves the block that starts with `first` and ends with `end` (inclusive) to just before `before`.
std::string move_block(std::string text, const std::string& first, const std::string& end, const std::string& before) {
    const auto start = text.find(first);
    const auto stop = text.find(end, start);
    EXPECT_NE(start, std::string::npos);
    EXPECT_NE(stop, std::string::npos);
    const std::string block = text.substr(start, stop + end.size() - start);
    text.erase(start, block.size());
    const auto at = text.find(before);
    EXPECT_NE(at, std::string::npos);
    text.insert(at, block);
    return text;
}

TEST(DiffSemantics, FileAgainstItselfIsIdentical) { expect_identical(diff_base, diff_base); }

TEST(DiffSemantics, NumberSpellingIsNotAChange) {
    std::string x = diff_base;
    x = edit(x, "<Index>#x1600</Index>\n          <Name>Outputs</Name>", "<Index>5632</Index>\n          <Name>Outputs</Name>");
    x = edit(x, "RevisionNo=\"#x00010000\">EX-1001", "RevisionNo=\"65536\">EX-1001");
    x = edit(x, "<AssignActivate>#x0300</AssignActivate>", "<AssignActivate>#x300</AssignActivate>");
    x = edit(x, "StartAddress=\"#x1400\"", "StartAddress=\"5120\"");
    x = edit(x, "<DefaultValue>#x60000108</DefaultValue>", "<DefaultValue>1610613000</DefaultValue>");
    x = edit(x, "<SubIndex>2</SubIndex>\n            <BitLen>8</BitLen>\n            <Name>Input B</Name>",
             "<SubIndex>#x02</SubIndex>\n            <BitLen>#x8</BitLen>\n            <Name>Input B</Name>");
    expect_identical(diff_base, x);
}

TEST(DiffSemantics, AttributeOrderIsNotAChange) {
    std::string x = diff_base;
    x = edit(x, "<Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"2\" Enable=\"1\">",
             "<Sm Enable=\"1\" DefaultSize=\"2\" ControlByte=\"#x64\" StartAddress=\"#x1100\">");
    x = edit(x, "<CoE SdoInfo=\"true\" PdoAssign=\"true\" CompleteAccess=\"false\">",
             "<CoE CompleteAccess=\"false\" PdoAssign=\"true\" SdoInfo=\"true\">");
    expect_identical(diff_base, x);
    // Unmodelled XML too: attribute order inside Info must not count.
    const std::string with = edit(diff_base, "</Electrical></Info>", "</Electrical><StateMachine a=\"1\" b=\"2\"/></Info>");
    expect_identical(with, edit(with, "<StateMachine a=\"1\" b=\"2\"/>", "<StateMachine b=\"2\" a=\"1\"/>"));
}

TEST(DiffSemantics, WhitespaceAndCommentsAreNotChanges) {
    // Drop all indentation, then add comments and whitespace inside elements.
    std::string x;
    bool line_start = true;
    for (const char c : std::string(diff_base)) {
        if (line_start && c == ' ') continue;
        line_start = c == '\n';
        x.push_back(c);
    }
    x = edit(x, "<Fmmu>Outputs</Fmmu>", "<!-- process data -->\n<Fmmu>Outputs</Fmmu>");
    x = edit(x, "<Name>Inputs mapping</Name>", "<Name>  Inputs mapping\n  </Name><!-- trailing -->");
    x = edit(x, "<ConfigData>080E00CC</ConfigData>", "<ConfigData>\n  080E 00CC\n</ConfigData>");
    expect_identical(diff_base, x);
}

TEST(DiffSemantics, WhitespaceInsideNamesIsNotAChange) {
    // A name wrapped over two lines is the same name (the reader trims only the ends).
    expect_identical(diff_base, edit(diff_base, "A device for tests", "A device\n          for  tests"));
}

TEST(DiffSemantics, HexDataCaseIsNotAChange) {
    std::string x = diff_base;
    x = edit(x, "<ConfigData>080E00CC</ConfigData>", "<ConfigData>080e00cc</ConfigData>");
    x = edit(x, "<Data>AABB</Data>", "<Data>aabb</Data>");
    x = edit(x, "<ImageData16x14>424D<", "<ImageData16x14>424d<");
    expect_identical(diff_base, x);
}

TEST(DiffSemantics, DefaultsCompareByTheirBytes) {
    // DefaultValue 5 of a UINT is the bytes 05 00: DefaultData 0500 is the same default.
    expect_identical(diff_base, edit(diff_base, "<DefaultValue>5</DefaultValue>", "<DefaultData>0500</DefaultData>"));
    expect_identical(diff_base, edit(diff_base, "<DefaultValue>5</DefaultValue>", "<DefaultValue>#x0005</DefaultValue>"));
    // A limit given as data compares as the number it encodes.
    expect_identical(diff_base, edit(diff_base, "<MaxValue>1000</MaxValue>", "<MaxData>E803</MaxData>"));
}

TEST(DiffSemantics, BooleanSpellingAndAbsentFalseAreNotChanges) {
    std::string x = diff_base;
    x = edit(x, "<RxPdo Fixed=\"true\" Sm=\"2\">", "<RxPdo Fixed=\"1\" Sm=\"2\">");
    x = edit(x, "<CoE SdoInfo=\"true\" PdoAssign=\"true\" CompleteAccess=\"false\">", "<CoE SdoInfo=\"1\" PdoAssign=\"true\">");
    x = edit(x, "<TxPdo>\n          <Index>#x1A10</Index>", "<TxPdo Mandatory=\"false\">\n          <Index>#x1A10</Index>");
    expect_identical(diff_base, x);
}

TEST(DiffSemantics, OrderWithoutMeaningIsNotAChange) {
    std::string x = diff_base;
    // Objects, data types, groups, devices, modules, DC modes, names per language.
    x = move_block(x, "<Object>\n                <Index>#x8000</Index>", "</Object>",
                   "<Object>\n                <Index>#x1A00</Index>");
    x = move_block(x, "<DataType>\n                <Name>DT8000</Name>", "</DataType>", "<DataType><Name>USINT</Name>");
    x = move_block(x, "<Group>\n        <Type>Drives</Type>", "</Group>", "<Group SortOrder=\"1\">");
    x = move_block(x, "<Device Physics=\"KK\">", "</Device>", "<Device Physics=\"YY\">");
    x = move_block(x, "<Module>\n        <Type ModuleIdent=\"#x00001200\"", "</Module>",
                   "<Module>\n        <Type ModuleIdent=\"#x00001100\"");
    x = move_block(x, "<OpMode>\n            <Name>FreeRun</Name>", "</OpMode>", "<OpMode>\n            <Name>DC</Name>");
    x = move_block(x, "<Name LcId=\"1031\">Beispielgerät</Name>", "</Name>", "<Name LcId=\"1033\">Example device</Name>");
    // A PDO that is not assigned by default may sit anywhere among the PDOs.
    x = move_block(x, "<TxPdo>\n          <Index>#x1A10</Index>", "</TxPdo>",
                   "<TxPdo Sm=\"3\">\n          <Index>#x1A00</Index>");
    expect_identical(diff_base, x);
}

TEST(DiffSemantics, TypeNamesCompareCanonically) {
    const std::string with =
        edit(diff_base, "<DataTypes>", "<DataTypes><DataType><Name>ARRAY [0..1] OF BYTE</Name><BitSize>16</BitSize></DataType>");
    expect_identical(with, edit(with, "ARRAY [0..1] OF BYTE", "ARRAY[0..1]  OF BYTE"));
    expect_identical(diff_base, edit(diff_base, "<SubIdx>1</SubIdx><Name>Filter</Name><Type>UDINT</Type>",
                                     "<SubIdx>1</SubIdx><Name>Filter</Name><Type> UDINT </Type>"));
}

TEST(DiffSemantics, MappingLettersAreASet) {
    const std::string rt = edit(diff_base, "<Access>ro</Access><PdoMapping>T</PdoMapping></Flags>",
                                "<Access>ro</Access><PdoMapping>RT</PdoMapping></Flags>");
    expect_identical(rt, edit(rt, "<PdoMapping>RT</PdoMapping>", "<PdoMapping>TR</PdoMapping>"));
}

TEST(DiffSemantics, RenamedDataTypeWithTheSameLayoutIsOnlyASpellingChange) {
    std::string x = diff_base;
    x = edit(x, "<Name>DT8000</Name>", "<Name>DT8000_V2</Name>");
    x = edit(x, "<Type>DT8000</Type>", "<Type>DT8000_V2</Type>");
    const esi::DiffResult r = diff_texts(diff_base, x);
    EXPECT_EQ(r.verdict, esi::Verdict::compatible) << esi::test::describe(r);  // the old type is gone, the new one is there
    const esi::Change* spelling = esi::test::find_change(r, ChangeKind::spelling_changed);
    ASSERT_NE(spelling, nullptr) << esi::test::describe(r);
    EXPECT_EQ(spelling->path, "Dictionary/Object[#x8000]/Type");
    EXPECT_EQ(esi::test::find_change(r, ChangeKind::object_entry_type_changed), nullptr);
}

TEST(DiffSemantics, EncodingOfTheFileIsNotAChange) {
    // The same content as ISO-8859-1 with a declaration, and as UTF-8 with a BOM.
    std::string latin1 = edit(diff_base, "encoding=\"UTF-8\"", "encoding=\"ISO-8859-1\"");
    latin1 = edit(latin1, "Beispielgerät", std::string("Beispielger\xE4t"));
    const std::string bom = "\xEF\xBB\xBF" + std::string(diff_base);
    expect_identical(diff_base, latin1);
    expect_identical(diff_base, bom);
}

TEST(DiffSemantics, EntryOrderIsLayout) {
    // Swapping two entries moves data in the process image: breaking, with the revision error.
    const std::string a = R"(<Entry>
            <Index>#x6000</Index>
            <SubIndex>1</SubIndex>
            <BitLen>8</BitLen>
            <Name>Input A</Name>
            <DataType>USINT</DataType>
          </Entry>
          )";
    std::string x = edit(diff_base, a, "");
    x = edit(x, "<Entry>\n            <Index>0</Index>", a + "<Entry>\n            <Index>0</Index>");
    const esi::DiffResult r = diff_texts(diff_base, x);
    ASSERT_NE(esi::test::find_change(r, ChangeKind::pdo_entry_moved), nullptr) << esi::test::describe(r);
    EXPECT_EQ(r.verdict, esi::Verdict::breaking);
    EXPECT_NE(esi::test::find_change(r, ChangeKind::revision_not_changed), nullptr);
}

TEST(DiffSemantics, ChangedDataTypeShowsOnEveryObjectThatUsesIt) {
    // DT1A00 grows by one entry; object 0x1A00 uses it and must show the new sub-index.
    std::string x =
        edit(diff_base,
             "<SubItem><SubIdx>2</SubIdx><Name>Entry "
             "2</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>48</BitOffs><Flags><Access>ro</Access></Flags></SubItem>",
             "<SubItem><SubIdx>2</SubIdx><Name>Entry "
             "2</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>48</BitOffs><Flags><Access>ro</Access></Flags></SubItem>"
             "<SubItem><SubIdx>3</SubIdx><Name>Entry "
             "3</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>80</BitOffs><Flags><Access>ro</Access></Flags></SubItem>");
    const esi::DiffResult r = diff_texts(diff_base, x);
    bool object_entry = false;
    for (const auto& c : r.changes)
        if (c.kind == ChangeKind::object_entry_added && c.path == "Dictionary/Object[#x1A00:03]") object_entry = true;
    EXPECT_TRUE(object_entry) << esi::test::describe(r);
    EXPECT_NE(esi::test::find_change(r, ChangeKind::data_type_changed), nullptr);
}

TEST(DiffSemantics, OutputIsDeterministic) {
    const std::string x = edit(edit(diff_base, "<BitLen>4</BitLen>", "<BitLen>8</BitLen>"), "</Devices>",
                               "<Device Physics=\"YY\"><Type ProductCode=\"#x00003003\" "
                               "RevisionNo=\"1\">EX-3003</Type><Name>Third</Name></Device></Devices>");
    const esi::DiffResult first = diff_texts(diff_base, x);
    const esi::DiffResult second = diff_texts(diff_base, x);
    ASSERT_EQ(first.changes.size(), second.changes.size());
    EXPECT_EQ(esi::test::describe(first), esi::test::describe(second));
}

}  // namespace

namespace {

TEST(DiffSemantics, InfoSubItemThatMatchesNoSubEntryIsStillCompared) {
    const std::string extra = "<SubItem><Name>Filter</Name><Info><DefaultValue>100</DefaultValue></Info></SubItem>";
    const std::string with =
        edit(diff_base, extra, extra + "<SubItem><Name>Spare</Name><Info><DefaultValue>7</DefaultValue></Info></SubItem>");
    const esi::DiffResult r = diff_texts(with, edit(with, "<DefaultValue>7</DefaultValue>", "<DefaultValue>8</DefaultValue>"));
    ASSERT_EQ(r.changes.size(), 1u) << esi::test::describe(r);
    EXPECT_EQ(r.changes[0].kind, ChangeKind::object_default_changed);
    EXPECT_EQ(r.changes[0].path, "Dictionary/Object[#x8000]/Info/SubItem[3]");
}

TEST(DiffSemantics, EmptyContainerElementsAreReportedAsSpelling) {
    const std::string a =
        "<?xml version=\"1.0\"?><EtherCATInfo><Vendor><Id>1</Id></Vendor><Descriptions><Devices/></Descriptions></EtherCATInfo>";
    const std::string b =
        "<?xml "
        "version=\"1.0\"?><EtherCATInfo><Vendor><Id>1</Id></Vendor><Descriptions><Devices/><Modules/></Descriptions></"
        "EtherCATInfo>";
    const esi::DiffResult r = diff_texts(a, b);
    ASSERT_EQ(r.changes.size(), 1u) << esi::test::describe(r);
    EXPECT_EQ(r.changes[0].kind, ChangeKind::spelling_changed);
    EXPECT_EQ(r.changes[0].change_class, esi::ChangeClass::cosmetic);
    EXPECT_EQ(r.changes[0].path, "EtherCATInfo/Modules");
}

}  // namespace

namespace {

// Two kept (unmodelled) elements that differ only by a repeated attribute: well-formed XML cannot
// hold one, but a model built by a library user can, and the differ must still name the change
// instead of reading past the end of the child list.
TEST(DiffSemantics, UnmodelledElementsDifferingOnlyByARepeatedAttributeAreAChange) {
    const std::string with = edit(diff_base, "<Info><Electrical>", "<Extra A=\"1\"/><Info><Electrical>");
    const esi::EsiDocument old_document = esi::test::read_document(with);
    esi::EsiDocument new_document = esi::test::read_document(with);
    ASSERT_FALSE(new_document.infos.empty());
    ASSERT_FALSE(new_document.infos[0].devices.empty());
    esi::Extras& extras = new_document.infos[0].devices[0].extras;
    auto extra = std::find_if(extras.elements.begin(), extras.elements.end(), [](const esi::XmlElement& e) { return e.name == "Extra"; });
    ASSERT_NE(extra, extras.elements.end());
    extra->attributes.push_back({"A", "1"});

    const esi::DiffResult r = esi::diff_documents(old_document, new_document);
    ASSERT_EQ(r.changes.size(), 1u) << esi::test::describe(r);
    EXPECT_EQ(r.changes[0].kind, ChangeKind::extras_changed);
    EXPECT_EQ(r.changes[0].path, "Extra@A") << esi::test::describe(r);
    EXPECT_EQ(r.changes[0].old_value, std::nullopt);
    EXPECT_EQ(r.changes[0].new_value, "1");
}

}  // namespace
