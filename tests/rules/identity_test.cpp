// Identity rules beyond the fixtures: one finding per fault, passive terminals, bus dumps, and the
// little-endian reading of DefaultData shared with the 0x1C00 check.
#include <gtest/gtest.h>

#include <algorithm>

#include "check/queries.hpp"
#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

std::size_t count(const esi::FileReport& report, std::string_view rule) {
    return static_cast<std::size_t>(
        std::count_if(report.diagnostics.begin(), report.diagnostics.end(), [&](const esi::Diagnostic& d) { return d.rule == rule; }));
}

esi::FileReport lint(const std::string& xml) { return esi::lint_bytes(xml, "test.xml", esi::EffectiveConfig{}); }

std::string info_with_device(const std::string& type_element) {
    return "<EtherCATInfo><Vendor><Id>#x00000E4A</Id><Name>Example</Name></Vendor><Descriptions>"
           "<Groups><Group><Type>G</Type><Name>G</Name></Group></Groups><Devices>"
           "<Device Physics=\"YY\">" +
           type_element +
           "<Name>D</Name><GroupType>G</GroupType>"
           "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>"
           "</Device></Devices></Descriptions></EtherCATInfo>";
}

TEST(IdentityRules, MalformedProductCodeIsReportedOnceAsANumberFault) {
    const auto report = lint(info_with_device("<Type ProductCode=\"12h\" RevisionNo=\"1\">D</Type>"));
    EXPECT_EQ(count(report, "xml-number-format"), 1u);
    EXPECT_EQ(count(report, "identity-product-code-missing"), 0u);
}

TEST(IdentityRules, AbsentProductCodeIsReportedEvenWhenAnotherAttributeIsMalformed) {
    const auto report = lint(info_with_device("<Type RevisionNo=\"1x\">D</Type>"));
    EXPECT_EQ(count(report, "identity-product-code-missing"), 1u);
    EXPECT_EQ(count(report, "identity-revision-missing"), 0u);  // written, but malformed
}

TEST(IdentityRules, AttributeNameInsideAnotherValueDoesNotCountAsWritten) {
    const auto report = lint(info_with_device("<Type RevisionNo=\"1\" Comment=\"see ProductCode=\">D</Type>"));
    EXPECT_EQ(count(report, "identity-product-code-missing"), 1u);
}

TEST(IdentityRules, SameDeviceTwiceInABusDumpIsNotADuplicate) {
    // EtherCATInfoList (IgH `ethercat xml`) lists one EtherCATInfo per slave on the bus.
    const std::string info =
        "<EtherCATInfo><Vendor><Id>2</Id><Name>B</Name></Vendor><Descriptions><Groups><Group><Type>G</Type><Name>G</Name>"
        "</Group></Groups><Devices><Device Physics=\"KK\"><Type ProductCode=\"#x03EC3052\" RevisionNo=\"#x00100000\">EL1004"
        "</Type><Name>EL1004</Name><GroupType>G</GroupType></Device></Devices></Descriptions></EtherCATInfo>";
    const auto report = lint("<EtherCATInfoList>" + info + info + "</EtherCATInfoList>");
    EXPECT_EQ(count(report, "identity-duplicate"), 0u);
}

TEST(IdentityRules, DuplicateNotePointsAtTheFirstDevice) {
    const std::string device =
        "<Device Physics=\"YY\"><Type ProductCode=\"#x1\" RevisionNo=\"#x2\">D</Type><Name>D</Name><GroupType>G</GroupType></Device>\n";
    const auto report = lint("<EtherCATInfo><Vendor><Id>1</Id><Name>V</Name></Vendor><Descriptions><Groups><Group><Type>G</Type>"
                             "<Name>G</Name></Group></Groups><Devices>\n" +
                             device + device + "</Devices></Descriptions></EtherCATInfo>");
    ASSERT_EQ(count(report, "identity-duplicate"), 1u);
    const auto it = std::find_if(report.diagnostics.begin(), report.diagnostics.end(),
                                 [](const esi::Diagnostic& d) { return d.rule == "identity-duplicate"; });
    EXPECT_EQ(it->pos.line, 3u);
    ASSERT_EQ(it->notes.size(), 1u);
    EXPECT_EQ(it->notes[0].pos.line, 2u);
    EXPECT_NE(it->message.find("#x00000001"), std::string::npos) << it->message;
}

TEST(IdentityRules, DefaultDataIsReadLittleEndian) {
    esi::ObjectInfo info;
    info.default_data = esi::HexData{"52487520", {}};
    esi::ObjectEntry entry;
    entry.info = &info;
    EXPECT_EQ(esi::rules::default_integer(entry), 0x20754852u);
    info.default_data = esi::HexData{"0", {}};
    EXPECT_EQ(esi::rules::default_integer(entry), std::nullopt);  // not hexBinary
    info.default_value = esi::Number::from_unsigned(7);
    EXPECT_EQ(esi::rules::default_integer(entry), 7u);  // DefaultValue wins
}

TEST(IdentityRules, PassiveTerminalsOfTheBeckhoffCatalogueNeedNoIdentity) {
    ESI_REQUIRE_CORPUS();
    const auto file = esi::test::corpus_esi_dir() / "Beckhoff__EL9xxx__dls-ethercat__2018-01.xml";
    const auto report = esi::lint_bytes(esi::test::read_text(file), file.string(), esi::EffectiveConfig{});
    EXPECT_EQ(count(report, "identity-product-code-missing"), 0u);
    EXPECT_EQ(count(report, "identity-revision-missing"), 0u);
}

TEST(IdentityRules, TemplateIdentityInTheEtgSampleIsFound) {
    ESI_REQUIRE_CORPUS();
    // The ETG ModulesSlots CiA402 sample declares vendor #xE0000001 but keeps Beckhoff's 0x1018.
    const auto file = esi::test::corpus_esi_dir() / "ETG__ModulesSlots_CiA402__siitool.xml";
    const auto report = esi::lint_bytes(esi::test::read_text(file), file.string(), esi::EffectiveConfig{});
    // Vendor id and product code are the foreign identity (errors); the revision is its own warning.
    EXPECT_EQ(count(report, "identity-1018-mismatch"), 2u);
    EXPECT_EQ(count(report, "identity-1018-revision-stale"), 1u);
}

}  // namespace
