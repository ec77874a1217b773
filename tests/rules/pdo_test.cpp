// Behaviour of the pdo-… rules beyond their fixtures: messages, positions, notes, and the cases
// where a rule must stay silent (modules, modular devices, oversampling, unreadable indices).

#include <gtest/gtest.h>

#include "rules/pdo_od_test_support.hpp"

namespace {

using esi::test::findings_of;
using esi::test::finding_lines;
using esi::test::lint_text;
using esi::test::lines_containing;
using esi::test::one_device;

std::string dictionary(const std::string& objects) {
    return "        <Profile><Dictionary><DataTypes/><Objects>\n" + objects + "        </Objects></Dictionary></Profile>\n";
}

std::string var_object(const std::string& index, const std::string& type, int bits, const std::string& mapping) {
    return "          <Object><Index>" + index + "</Index><Name>O" + index + "</Name><Type>" + type + "</Type><BitSize>" +
           std::to_string(bits) + "</BitSize><Flags><Access>rw</Access><PdoMapping>" + mapping + "</PdoMapping></Flags></Object>\n";
}

TEST(PdoRules, BitLenMessageNamesEntryBitLenAndType) {
    const std::string xml = one_device(std::string(esi::test::standard_sms) +
                                       "        <TxPdo Sm=\"3\"><Index>#x1A00</Index><Name>In</Name>\n"
                                       "          <Entry><Index>#x6064</Index><SubIndex>0</SubIndex>\n"
                                       "            <BitLen>16</BitLen>\n"
                                       "            <DataType>DINT</DataType></Entry>\n"
                                       "        </TxPdo>\n");
    const auto found = findings_of(lint_text(xml), "pdo-entry-bitlen-type");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].message, "Entry #x6064:00 has BitLen 16 but DINT is 32 bits");
    EXPECT_EQ(found[0].pos.line, *lines_containing(xml, "<BitLen>16</BitLen>").begin());
    EXPECT_EQ(found[0].severity, esi::Severity::error);
}

TEST(PdoRules, UnreadableEntryIndexIsNeitherPaddingNorAnObject) {
    // Pollen Robotics files write "#x0x6041"; the reader reports the number, the entry must not be
    // mistaken for padding (pdo-padding-subindex) and is named by its Name.
    const std::string xml = one_device(std::string(esi::test::standard_sms) +
                                       "        <RxPdo Sm=\"2\"><Index>#x1600</Index><Name>Out</Name>\n"
                                       "          <Entry><Index>#x0x6041</Index><SubIndex>1</SubIndex><BitLen>16</BitLen>"
                                       "<Name>controlword</Name><DataType>UINT16</DataType></Entry>\n"
                                       "        </RxPdo>\n" + esi::test::coe_mailbox);
    const auto report = lint_text(xml);
    EXPECT_EQ(findings_of(report, "xml-number-format").size(), 1u);
    EXPECT_TRUE(findings_of(report, "pdo-padding-subindex").empty());
    const auto type = findings_of(report, "pdo-entry-type-spelling");
    ASSERT_EQ(type.size(), 1u);
    EXPECT_EQ(type[0].message, "Entry 'controlword' has DataType 'UINT16', which is not an ESI type name; the standard name is 'UINT'");
}

TEST(PdoRules, LegacyRefPdosAreOneFindingPerFileNotAMissingIndexEach) {
    // Before ETG.2000 a PDO named its description with Ref= (Beckhoff EtherCAT_Terminals).
    const std::string xml = one_device(std::string(esi::test::standard_sms) +
                                       "        <RxPdo Ref=\"AX2000Out\" Fixed=\"1\" Sm=\"2\"/>\n"
                                       "        <TxPdo Ref=\"AX2000In\" Fixed=\"1\" Sm=\"3\"/>\n"
                                       "        <TxPdo Sm=\"3\"><Name>No index, no reference</Name></TxPdo>\n");
    const auto report = lint_text(xml);
    const auto legacy = findings_of(report, "pdo-legacy-ref");
    ASSERT_EQ(legacy.size(), 1u);
    EXPECT_NE(legacy[0].message.find("and so do 1 more PDO of this file"), std::string::npos) << legacy[0].message;
    // Only the PDO with neither Index nor Ref misses its Index.
    EXPECT_EQ(findings_of(report, "xml-missing-element").size(), 1u);
}

TEST(PdoRules, The256thPdoOfADirectionIsReportedOnce) {
    std::string pdos;
    for (int i = 0; i < 256; ++i) {
        char index[8];
        std::snprintf(index, sizeof index, "%04X", 0x1A00 + i);
        pdos += std::string("        <TxPdo><Index>#x") + index + "</Index><Name>P" + std::to_string(i) + "</Name></TxPdo>\n";
    }
    const std::string xml = one_device(std::string(esi::test::standard_sms) + pdos + esi::test::coe_mailbox);
    const auto found = findings_of(lint_text(xml), "pdo-mapping-limits");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pos.line, *lines_containing(xml, "<Index>#x1AFF</Index>").begin());
    EXPECT_NE(found[0].message.find("number 256 of 256"), std::string::npos) << found[0].message;
}

TEST(PdoRules, DuplicateIndexNotePointsAtTheFirstDeclaration) {
    const std::string xml = one_device(std::string(esi::test::standard_sms) +
                                       "        <RxPdo><Index>#x1600</Index><Name>A</Name></RxPdo>\n"
                                       "        <TxPdo><Index>#x1600</Index><Name>B</Name></TxPdo>\n" + esi::test::coe_mailbox);
    const auto found = findings_of(lint_text(xml), "pdo-duplicate-index");
    ASSERT_EQ(found.size(), 1u);
    const auto lines = lines_containing(xml, "<Index>#x1600</Index>");
    EXPECT_EQ(found[0].pos.line, *lines.rbegin());
    ASSERT_EQ(found[0].notes.size(), 1u);
    EXPECT_EQ(found[0].notes[0].pos.line, *lines.begin());
    // The same fault is also a TxPdo outside its area: a second rule, not a duplicate finding (a
    // warning, as this CoE neither assigns nor configures PDOs).
    EXPECT_EQ(findings_of(lint_text(xml), "pdo-index-area").size(), 1u);
}

TEST(PdoRules, ModuleEntriesWithSlotDependentIndicesAreNotLookedUp) {
    const std::string xml =
        "<?xml version=\"1.0\"?>\n"
        "<EtherCATModule Version=\"1.3\"><Vendor><Id>2</Id></Vendor><Modules>\n"
        "<Module><Type ModuleIdent=\"#x8201\">M</Type><Name>M</Name>\n"
        "<TxPdo Fixed=\"1\" Sm=\"3\"><Index DependOnSlot=\"1\">#x1a00</Index><Name>In</Name>\n"
        "<Entry><Index DependOnSlot=\"1\">#x6000</Index><SubIndex>9</SubIndex><BitLen>1</BitLen><DataType>BOOL</DataType></Entry>\n"
        "</TxPdo>\n"
        "<RxPdo Fixed=\"1\" Sm=\"2\"><Index>#x1a01</Index><Name>Out</Name></RxPdo>\n"
        "<Profile><Dictionary><DataTypes/><Objects><Object><Index>#x7000</Index><Name>X</Name><Type>USINT</Type>"
        "<BitSize>8</BitSize></Object></Objects></Dictionary></Profile>\n"
        "</Module></Modules></EtherCATModule>\n";
    const auto report = lint_text(xml);
    EXPECT_TRUE(findings_of(report, "pdo-entry-object-missing").empty());
    EXPECT_TRUE(findings_of(report, "pdo-entry-object-bitlen").empty());
    EXPECT_TRUE(findings_of(report, "pdo-sm-unknown").empty()) << "a module's Sm refers to the device's SMs";
    // Module PDOs are CoE mapping objects too: the RxPdo at #x1A01 is still reported, as a warning
    // since no device of the file says whether a master writes the index.
    EXPECT_EQ(findings_of(report, "pdo-index-area").size(), 1u);
    EXPECT_TRUE(findings_of(report, "pdo-index-range").empty());
}

TEST(PdoRules, ModularDevicesDoNotRequireEveryMappedObject) {
    const std::string body = std::string(esi::test::standard_sms) + dictionary(var_object("#x7000", "USINT", 8, "R")) +
                             "        <RxPdo Sm=\"2\"><Index>#x1600</Index><Name>Out</Name>\n"
                             "          <Entry><Index>#x7100</Index><SubIndex>1</SubIndex><BitLen>8</BitLen><DataType>USINT</DataType></Entry>\n"
                             "        </RxPdo>\n" + esi::test::coe_mailbox;
    EXPECT_EQ(findings_of(lint_text(one_device(body)), "pdo-entry-object-missing").size(), 1u);
    const std::string modular = body + "        <Slots><Slot MinInstances=\"0\" MaxInstances=\"1\"><Name>S</Name>"
                                       "<ModuleIdent>#x1</ModuleIdent></Slot></Slots>\n";
    EXPECT_TRUE(findings_of(lint_text(one_device(modular)), "pdo-entry-object-missing").empty());
}

TEST(PdoRules, OversamplingPdosAreNotComparedWithTheDictionary) {
    // Beckhoff EL37xx: an oversampling PDO maps #x6000:02 as a 16-bit sample while the object's
    // sub-index 2 is a status bit; OSFac/OSIndexInc shift the entries per sample.
    const std::string objects = "          <Object><Index>#x6000</Index><Name>Status</Name><Type>DT6000</Type><BitSize>24</BitSize></Object>\n";
    const std::string types =
        "<DataType><Name>DT6000</Name><BitSize>24</BitSize>"
        "<SubItem><SubIdx>0</SubIdx><Name>N</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs></SubItem>"
        "<SubItem><SubIdx>2</SubIdx><Name>Underrange</Name><Type>BOOL</Type><BitSize>1</BitSize><BitOffs>16</BitOffs>"
        "<Flags><Access>ro</Access><PdoMapping>T</PdoMapping></Flags></SubItem></DataType>";
    const auto body = [&](const std::string& attributes) {
        return std::string(esi::test::standard_sms) + "        <Profile><Dictionary><DataTypes>" + types + "</DataTypes><Objects>\n" +
               objects + "        </Objects></Dictionary></Profile>\n" + "        <TxPdo Sm=\"3\"" + attributes +
               "><Index>#x1A41</Index><Name>Sample</Name>\n"
               "          <Entry><Index>#x6000</Index><SubIndex>2</SubIndex><BitLen>16</BitLen><DataType>INT</DataType></Entry>\n"
               "        </TxPdo>\n" + esi::test::coe_mailbox;
    };
    EXPECT_EQ(findings_of(lint_text(one_device(body(""))), "pdo-entry-object-bitlen").size(), 1u);
    const auto oversampled = lint_text(one_device(body(" OSFac=\"10\" OSMin=\"1\" OSMax=\"50\" OSIndexInc=\"1\"")));
    EXPECT_TRUE(findings_of(oversampled, "pdo-entry-object-bitlen").empty());
    EXPECT_TRUE(findings_of(oversampled, "pdo-entry-object-type").empty());
}

TEST(PdoRules, SignednessMismatchIsOneFindingEvenWhenTheSizeDiffersToo) {
    // INT entry on a 1-bit BOOL sub-item: the size finding names both types; no second finding.
    const std::string xml = one_device(std::string(esi::test::standard_sms) +
                                       dictionary(var_object("#x6000", "BOOL", 1, "T")) +
                                       "        <TxPdo Sm=\"3\"><Index>#x1A00</Index><Name>In</Name>\n"
                                       "          <Entry><Index>#x6000</Index><BitLen>16</BitLen><DataType>INT</DataType></Entry>\n"
                                       "        </TxPdo>\n" + esi::test::coe_mailbox);
    const auto report = lint_text(xml);
    const auto bitlen = findings_of(report, "pdo-entry-object-bitlen");
    ASSERT_EQ(bitlen.size(), 1u);
    EXPECT_EQ(bitlen[0].message, "Entry #x6000:00 has BitLen 16 (INT) but object #x6000 'O#x6000' is BOOL, 1 bit");
    EXPECT_TRUE(findings_of(report, "pdo-entry-object-type").empty());
}

TEST(PdoRules, AssignmentDefaultsMayBeWrittenAsDefaultValue) {
    // SOES and EEPROM_generator write 0x1C12 sub-entries as DefaultValue #x1600 rather than
    // little-endian DefaultData.
    const auto xml = [](const std::string& value) {
        return one_device(
            std::string(esi::test::standard_sms) +
            "        <Profile><Dictionary><DataTypes>"
            "<DataType><Name>DT1C12ARR</Name><BaseType>UINT</BaseType><BitSize>16</BitSize><ArrayInfo><LBound>1</LBound><Elements>1</Elements></ArrayInfo></DataType>"
            "<DataType><Name>DT1C12</Name><BitSize>32</BitSize>"
            "<SubItem><SubIdx>0</SubIdx><Name>N</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs></SubItem>"
            "<SubItem><Name>Elements</Name><Type>DT1C12ARR</Type><BitSize>16</BitSize><BitOffs>16</BitOffs></SubItem></DataType>"
            "</DataTypes><Objects>\n"
            "          <Object><Index>#x1C12</Index><Name>RxPDO assign</Name><Type>DT1C12</Type><BitSize>32</BitSize>\n"
            "            <Info><SubItem><Name>N</Name><Info><DefaultValue>1</DefaultValue></Info></SubItem>"
            "<SubItem><Name>SubIndex 001</Name><Info><DefaultValue>" + value + "</DefaultValue></Info></SubItem></Info></Object>\n"
            "        </Objects></Dictionary></Profile>\n"
            "        <RxPdo Sm=\"2\"><Index>#x1600</Index><Name>Out</Name></RxPdo>\n" + esi::test::coe_mailbox);
    };
    EXPECT_TRUE(findings_of(lint_text(xml("#x1600")), "pdo-assign-default").empty());
    const auto found = findings_of(lint_text(xml("#x1601")), "pdo-assign-default");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].message, "the default of #x1C12 (SM2 PDO assignment) lists #x1601, but the PDOs with Sm=\"2\" are #x1600");
}

TEST(PdoRules, ExampleDigitalIoSampleIsClean) {
    const auto text = esi::test::read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml");
    const auto report = lint_text(text);
    for (const auto& d : report.diagnostics) ADD_FAILURE() << d.pos.line << ": " << d.rule << ": " << d.message;
}

}  // namespace
