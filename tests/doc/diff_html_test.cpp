// The HTML diff (esi/doc/diff_html.hpp, esi-diff --format html): entries paired and marked,
// breaking changes first, pictures only where the process data differs.

#include <gtest/gtest.h>

#include "doc/layout_marks.hpp"
#include "doc_test_support.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/doc/diff_html.hpp"

namespace {

namespace fs = std::filesystem;
using esi::doc::FieldMark;
using esi::doc::LayoutField;
using esi::test::run;
using esi::test::tool;
using namespace esi::test::doc;

LayoutField entry(const char* address, std::uint64_t offset, std::uint64_t size) {
    LayoutField f;
    f.name = address;
    f.address = address;
    f.bit_offset = offset;
    f.bit_size = size;
    return f;
}

std::vector<FieldMark> marks(const std::vector<LayoutField>& fields) {
    std::vector<FieldMark> out;
    for (const auto& f : fields) out.push_back(f.mark);
    return out;
}

TEST(LayoutMarks, EntriesPairByAddressAndAreMarkedOnBothSides) {
    std::vector<LayoutField> old_fields{entry("0x6000:01", 0, 8), entry("0x6000:02", 8, 16), entry("0x6000:03", 24, 8), entry("0x6000:04", 32, 8)};
    std::vector<LayoutField> new_fields{entry("0x6000:01", 0, 8), entry("0x6000:02", 8, 32), entry("0x6000:04", 40, 8), entry("0x6000:05", 48, 8)};
    esi::doc::mark_changes(old_fields, new_fields);
    EXPECT_EQ(marks(old_fields), (std::vector<FieldMark>{FieldMark::none, FieldMark::resized, FieldMark::removed, FieldMark::moved}));
    EXPECT_EQ(marks(new_fields), (std::vector<FieldMark>{FieldMark::none, FieldMark::resized, FieldMark::moved, FieldMark::added}));
}

TEST(LayoutMarks, RepeatedMappingsPairInOrderAndPaddingIsNotMarked) {
    LayoutField pad = entry("", 8, 8);
    pad.padding = true;
    std::vector<LayoutField> old_fields{entry("0x7000:01", 0, 8), pad, entry("0x7000:01", 16, 8)};
    std::vector<LayoutField> new_fields{entry("0x7000:01", 0, 8), entry("0x7000:01", 8, 8)};
    esi::doc::mark_changes(old_fields, new_fields);
    EXPECT_EQ(marks(old_fields), (std::vector<FieldMark>{FieldMark::none, FieldMark::none, FieldMark::moved}));
    EXPECT_EQ(marks(new_fields), (std::vector<FieldMark>{FieldMark::none, FieldMark::moved}));
    EXPECT_FALSE(esi::doc::same_layout(old_fields, new_fields));
    EXPECT_TRUE(esi::doc::same_layout(new_fields, new_fields));
}

fs::path diff_data() { return esi::test::source_dir() / "tests" / "diff" / "data"; }

std::string html_diff(const fs::path& old_path, const fs::path& new_path) {
    esi::DiffOptions options;
    options.keep_documents = true;
    const esi::FileDiff diff = esi::diff_files(old_path, new_path, options);
    EXPECT_TRUE(diff.result && diff.old_document && diff.new_document);
    if (!diff.result || !diff.old_document || !diff.new_document) return {};
    esi::doc::DiffHtmlOptions html_options;
    html_options.template_dirs = esi::doc::template_search_path({}, std::nullopt);
    const esi::doc::DiffHtml html =
        esi::doc::render_diff_html(*diff.old_document, *diff.new_document, *diff.result, {old_path.filename().string(), new_path.filename().string()}, html_options);
    EXPECT_FALSE(html.diagnostics.has_errors());
    return html.html;
}

// The text of the element with id `id` up to the next element with an id of the same prefix.
std::string block(const std::string& html, const std::string& id) {
    const std::size_t start = html.find("id=\"" + id + "\"");
    if (start == std::string::npos) return {};
    return html.substr(start, html.find("<h3 id=", start + 1) - start);
}

TEST(DiffHtml, BreakingChangesComeFirstThenEachDeviceMostSevereFirst) {
    const std::string html = html_diff(diff_data() / "old.xml", diff_data() / "new.xml");
    const std::size_t breaking = html.find("<section id=\"breaking\">");
    const std::size_t first_device = html.find("<section class=\"device\"");
    ASSERT_NE(breaking, std::string::npos);
    ASSERT_NE(first_device, std::string::npos);
    EXPECT_LT(breaking, first_device);
    EXPECT_NE(html.find("<span class=\"verdict breaking\">breaking</span>"), std::string::npos);
    // The error (breaking change under the same RevisionNo) leads the breaking table.
    EXPECT_LT(html.find("[revision-not-changed]", breaking), html.find("[pdo-entry-bit-len-changed]", breaking));
    EXPECT_NE(html.find("class=\"caution\""), std::string::npos);
}

TEST(DiffHtml, AResizedEntryIsMarkedInItsPdoAndInItsSyncManagerImageOnBothSides) {
    const std::string html = html_diff(diff_data() / "old.xml", diff_data() / "new.xml");
    const std::string pdo = block(html, "d0-rx1600");
    ASSERT_FALSE(pdo.empty()) << "no picture pair for RxPdo 0x1600";
    EXPECT_EQ(occurrences(pdo, "class=\"entry group-0 mark-resized\""), 2u);
    EXPECT_NE(pdo.find("0x7000:00, UDINT, 32 bits at byte 0 bit 0 (resized)"), std::string::npos);
    EXPECT_NE(pdo.find("0x7000:00, UINT, 16 bits at byte 0 bit 0 (resized)"), std::string::npos);
    const std::string sm = block(html, "d0-sm2");
    EXPECT_EQ(occurrences(sm, "mark-resized"), 2u);
}

TEST(DiffHtml, APdoOnlyOneFileHasShowsTheOtherSideAsAbsent) {
    const std::string html = html_diff(diff_data() / "old.xml", diff_data() / "new.xml");
    const std::string added = block(html, "d0-tx1A11");
    ASSERT_FALSE(added.empty()) << "no picture pair for TxPdo 0x1A11";
    EXPECT_NE(added.find("not in this file"), std::string::npos);
}

TEST(DiffHtml, PicturesBothFilesAgreeOnAreLeftOut) {
    const std::string html = html_diff(diff_data() / "old.xml", diff_data() / "new.xml");
    EXPECT_TRUE(block(html, "d0-tx1A00").empty());  // TxPdo 0x1A00 is the same in both
    EXPECT_TRUE(block(html, "d0-sm3").empty());
}

TEST(DiffHtml, IdenticalFilesSaySoAndDrawNothing) {
    const std::string html = html_diff(diff_data() / "old.xml", diff_data() / "old.xml");
    EXPECT_NE(html.find("no change at all"), std::string::npos);
    EXPECT_EQ(html.find("<svg"), std::string::npos);
    EXPECT_EQ(html.find("id=\"breaking\""), std::string::npos);
}

TEST(DiffHtml, EsiDiffWritesTheHtmlReportAndKeepsItsExitCodes) {
    const auto r = run({tool("esi-diff").string(), (diff_data() / "old.xml").string(), (diff_data() / "new.xml").string(), "--format", "html"});
    EXPECT_EQ(r.exit_code, 1);  // breaking
    EXPECT_EQ(r.out.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_EQ(r.out, run({tool("esi-diff").string(), (diff_data() / "old.xml").string(), (diff_data() / "new.xml").string(), "--format", "html"}).out);
    const auto same = run({tool("esi-diff").string(), (diff_data() / "old.xml").string(), (diff_data() / "old.xml").string(), "--format", "html"});
    EXPECT_EQ(same.exit_code, 0);
}

TEST(DiffHtml, TheRevisionPairsOfTheCorpusRender) {
    ESI_REQUIRE_CORPUS();
    const fs::path c = esi::test::corpus_esi_dir();
    const std::vector<std::pair<std::string, std::string>> pairs{
        {"MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-02.xml", "MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-10.xml"},
        {"ProjectMARCH__BP-GES__ethercat-slaves__2020-02.xml", "ProjectMARCH__BP-GES__ethercat-slaves__2020-03.xml"},
        {"PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml", "PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml"},
        {"Beckhoff__EL1xxx__dls-ethercat__2011-05.xml", "Beckhoff__EL1xxx__dls-ethercat__2011-08.xml"}};
    for (const auto& [a, b] : pairs) {
        const std::string html = html_diff(c / a, c / b);
        EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u) << a;
        EXPECT_NE(html.find("</html>"), std::string::npos) << a;
    }
    // NeckOrbita moved its process data from SM0/SM1 to SM2/SM3: both images are drawn, one per side.
    const std::string neck = html_diff(c / pairs[2].first, c / pairs[2].second);
    EXPECT_NE(neck.find("Process image of SM2"), std::string::npos);
    EXPECT_NE(neck.find("not in this file"), std::string::npos);
}

}  // namespace
