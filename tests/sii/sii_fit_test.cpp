// Images larger than Eeprom/ByteSize (docs/sii.md §1, "Images larger than the EEPROM"): the
// builder leaves out optional content in the documented order until the image fits, names each
// part in a note, and fails only when the mandatory part does not fit; fit_to_eeprom off
// (--strict-size) refuses instead.
//
// Sizes of the fixture device (fixture.hpp), without a ByteSize limit: 436 bytes whole, 322
// without the PDO categories, 364 without the DC category, 248 without both (the mandatory part).

#include <gtest/gtest.h>

#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "fixture.hpp"

namespace {

using namespace esi::sii;
using esi::Severity;
using esi::test::build_fixture;
using esi::test::fixture_xml;
using esi::test::has_rule;

std::string replaced(std::string text, const std::string& what, const std::string& with) {
    const auto at = text.find(what);
    EXPECT_NE(at, std::string::npos) << what;
    if (at != std::string::npos) text.replace(at, what.size(), with);
    return text;
}

// The fixture without its CoE element: a master then knows the PDOs only from the SII (or ESI).
std::string without_coe(const std::string& xml) {
    return replaced(xml, R"(<CoE SdoInfo="true" PdoAssign="true" PdoConfig="false" CompleteAccess="true"/>)", "");
}

std::size_t notes(const BuildResult& r) {
    std::size_t n = 0;
    for (const auto& d : r.diagnostics) n += d.rule == "sii-left-out" && d.severity == Severity::info;
    return n;
}

TEST(SiiFit, AnImageThatFitsIsWhole) {
    const BuildResult r = build_fixture(fixture_xml({}, "512"));
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(r.omitted.any());
    EXPECT_TRUE(r.left_out.empty());
    EXPECT_EQ(notes(r), 0u);
    EXPECT_EQ(r.content_bytes, 436u);
}

TEST(SiiFit, PdoCategoriesOfACoeDeviceGoFirst) {
    const BuildResult r = build_fixture(fixture_xml({}, "384"));
    ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    EXPECT_TRUE(r.omitted.pdos);
    EXPECT_FALSE(r.omitted.dc);
    ASSERT_EQ(r.left_out.size(), 1u);
    EXPECT_EQ(r.left_out[0], "the TxPDO and RxPDO categories (3 PDOs)");
    ASSERT_EQ(notes(r), 1u);
    const DecodedImage d = decode_image(r.bytes);
    EXPECT_TRUE(d.faults.empty());
    EXPECT_EQ(d.image.find(category::tx_pdo), nullptr);
    EXPECT_EQ(d.image.find(category::rx_pdo), nullptr);
    ASSERT_NE(d.image.dc(), nullptr);
    EXPECT_EQ(r.bytes.size(), 384u);  // padded to the EEPROM, as a whole image is
    // The note names the part, the sizes and the reason, at Eeprom/ByteSize.
    for (const auto& n : r.diagnostics)
        if (n.rule == "sii-left-out") {
            EXPECT_NE(n.message.find("(436 bytes with everything, 322 without)"), std::string::npos) << n.message;
            EXPECT_NE(n.message.find("over CoE"), std::string::npos) << n.message;
            EXPECT_TRUE(n.pos.known());
        }
}

TEST(SiiFit, StrictSizeRefusesWhatTheFitWouldShrink) {
    BuildOptions strict;
    strict.fit_to_eeprom = false;
    const BuildResult r = build_fixture(fixture_xml({}, "384"), strict);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-image-too-large", Severity::error));
    EXPECT_FALSE(r.omitted.any());
    for (const auto& d : r.diagnostics) {
        if (d.rule == "sii-image-too-large") { EXPECT_NE(d.message.find("--strict-size"), std::string::npos) << d.message; }
    }
}

TEST(SiiFit, ThenDcDescriptionsThenTheDcCategory) {
    // 256 bytes: without PDOs 322, without the description "SYNC0" still too large, without DC 248.
    const BuildResult r = build_fixture(fixture_xml({}, "256"));
    ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    EXPECT_TRUE(r.omitted.pdos);
    EXPECT_TRUE(r.omitted.dc_descriptions);
    EXPECT_TRUE(r.omitted.dc);
    ASSERT_EQ(r.left_out.size(), 3u);
    EXPECT_EQ(r.left_out[1], "the descriptions of the DC op modes (1 string)");
    EXPECT_EQ(r.left_out[2], "the DC category (2 op modes)");
    EXPECT_EQ(notes(r), 3u);
    EXPECT_EQ(r.content_bytes, 248u);
}

TEST(SiiFit, DcDescriptionsAloneWhenThatIsEnough) {
    // Without CoE the PDOs stay; a 100-character description is what does not fit 512 bytes.
    const std::string xml = replaced(without_coe(fixture_xml({}, "512")), "<Desc>SYNC0</Desc>", "<Desc>" + std::string(100, 'd') + "</Desc>");
    const BuildResult r = build_fixture(xml);
    ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    EXPECT_FALSE(r.omitted.pdos);
    EXPECT_TRUE(r.omitted.dc_descriptions);
    EXPECT_FALSE(r.omitted.dc);
    const DecodedImage d = decode_image(r.bytes);
    ASSERT_NE(d.image.dc(), nullptr);
    for (const auto& op : d.image.dc()->items) EXPECT_EQ(op.desc_idx, 0);
    EXPECT_NE(d.image.find(category::tx_pdo), nullptr);
}

TEST(SiiFit, WithoutCoeUnassignedPdosGoBeforeTheDefaultAssignment) {
    // TxPdo 0x1A01 has no Sm: give it 12 entries, then 384 bytes hold the device only without it.
    std::string entries;
    for (int i = 1; i <= 12; ++i)
        entries += "<Entry><Index>#x6001</Index><SubIndex>" + std::to_string(i) + "</SubIndex><BitLen>8</BitLen><Name>Extra " +
                   std::to_string(i) + "</Name><DataType>USINT</DataType></Entry>";
    const std::string xml =
        replaced(without_coe(fixture_xml({}, "384")), "<Index>#x1A01</Index><Name>Optional</Name>", "<Index>#x1A01</Index><Name>Optional</Name>" + entries);
    const BuildResult r = build_fixture(xml);
    ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    EXPECT_TRUE(r.omitted.dc);
    EXPECT_TRUE(r.omitted.unassigned_pdos);
    EXPECT_FALSE(r.omitted.pdos);
    EXPECT_EQ(r.left_out.back(), "the PDOs without an Sm (1 PDO), not assigned by default");
    const DecodedImage d = decode_image(r.bytes);
    ASSERT_NE(d.image.pdos(category::tx_pdo), nullptr);
    ASSERT_EQ(d.image.pdos(category::tx_pdo)->items.size(), 1u);
    EXPECT_EQ(d.image.pdos(category::tx_pdo)->items[0].index, 0x1A00);
    ASSERT_NE(d.image.pdos(category::rx_pdo), nullptr);
}

TEST(SiiFit, WithoutCoeThePdoCategoriesGoLast) {
    const BuildResult r = build_fixture(without_coe(fixture_xml({}, "256")));
    ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    EXPECT_TRUE(r.omitted.pdos);
    EXPECT_TRUE(r.omitted.dc);
    EXPECT_EQ(r.left_out.back(), "the TxPDO and RxPDO categories");
    EXPECT_EQ(r.content_bytes, 248u);
}

TEST(SiiFit, TheMandatoryPartThatDoesNotFitIsAnError) {
    const BuildResult r = build_fixture(fixture_xml({}, "128"));
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(has_rule(r.diagnostics, "sii-image-too-large", Severity::error));
    EXPECT_EQ(notes(r), 0u);
    for (const auto& d : r.diagnostics)
        if (d.rule == "sii-image-too-large") {
            // After every step, the General strings too (docs/sii.md §1, steps 6-8).
            EXPECT_NE(d.message.find("the image takes 216 bytes"), std::string::npos) << d.message;
            EXPECT_NE(d.message.find("the device name (General, Name)"), std::string::npos) << d.message;
            EXPECT_NE(d.message.find("the mandatory part"), std::string::npos) << d.message;
        }
}

TEST(SiiFit, NoPdoAndNoDcAreOptionsNotOmissions) {
    BuildOptions options;
    options.include_pdos = false;
    options.include_dc = false;
    const BuildResult r = build_fixture(fixture_xml({}, "256"), options);
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(r.omitted.any());
    EXPECT_EQ(notes(r), 0u);
}

TEST(SiiFit, TooManyStringsAreCuredByLeavingOutPdos) {
    // 300 PDOs with distinct names: more than the 255 strings the count byte allows, but the
    // mandatory part has three.
    std::string pdos;
    for (int i = 0; i < 300; ++i)
        pdos += "<TxPdo><Index>#x" + std::to_string(1000 + i) + "</Index><Name>PDO " + std::to_string(i) + "</Name></TxPdo>";
    const std::string xml = replaced(fixture_xml({}, "8192"), "<TxPdo>\n          <Index>#x1A01</Index>", pdos + "<TxPdo>\n          <Index>#x1A01</Index>");
    BuildOptions strict;
    strict.fit_to_eeprom = false;
    EXPECT_TRUE(has_rule(build_fixture(xml, strict).diagnostics, "sii-too-many-strings", Severity::error));
    const BuildResult r = build_fixture(xml);
    ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
    EXPECT_TRUE(r.omitted.pdos);
}

}  // namespace

namespace {

// What the fit leaves out is optional for `check` as well: a fitted image checks clean against
// its ESI at every step.
TEST(SiiFit, FittedImagesCheckCleanAgainstTheirEsi) {
    std::string entries;
    for (int i = 1; i <= 12; ++i)
        entries += "<Entry><Index>#x6001</Index><SubIndex>" + std::to_string(i) + "</SubIndex><BitLen>8</BitLen><Name>Extra " +
                   std::to_string(i) + "</Name><DataType>USINT</DataType></Entry>";
    const std::string base = replaced(without_coe(fixture_xml({}, "BYTES")), "<Index>#x1A01</Index><Name>Optional</Name>",
                                      "<Index>#x1A01</Index><Name>Optional</Name>" + entries);
    for (const std::string bytes : {"512", "384", "256"}) {
        SCOPED_TRACE(bytes);
        const std::string xml = replaced(base, "<ByteSize>BYTES</ByteSize>", "<ByteSize>" + bytes + "</ByteSize>");
        const esi::test::Fixture f = esi::test::load_fixture(xml);
        const BuildResult r = build_image(f.info(), f.device(), {}, "fixture.xml");
        ASSERT_TRUE(r.ok()) << r.diagnostics.items().front().message;
        EXPECT_TRUE(r.omitted.any());
        const esi::Diagnostics mismatches = check_image(f.info(), f.device(), decode_image(r.bytes), "fixture.xml", "image.bin");
        EXPECT_FALSE(mismatches.has_errors()) << mismatches.items().front().message;
        EXPECT_EQ(mismatches.count(Severity::warning), 0u);
    }
}

}  // namespace
