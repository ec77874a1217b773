// The three report formats, as golden files: tests/diff/data/{old,new}.xml rendered as text, JSON
// and Markdown must equal tests/diff/golden/*. After an intended change of a report, regenerate
// them with ESI_UPDATE_GOLDEN=1 ./build/tests/diff_tests --gtest_filter='DiffReport*' and review
// the difference before committing.

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include <nlohmann/json.hpp>

#include "esi/diff/report.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

fs::path data(const std::string& name) { return esi::test::source_dir() / "tests" / "diff" / "data" / name; }
fs::path golden(const std::string& name) { return esi::test::source_dir() / "tests" / "diff" / "golden" / name; }

esi::DiffResult sample_result() {
    const esi::FileDiff diff = esi::diff_files(data("old.xml"), data("new.xml"));
    EXPECT_TRUE(diff.result.has_value());
    return diff.result ? *diff.result : esi::DiffResult{};
}

const esi::DiffLabels labels{"old.xml", "new.xml"};

void check_golden(const std::string& name, const std::string& actual) {
    const fs::path path = golden(name);
    if (esi::test::rewrite_golden(path, actual)) GTEST_SKIP() << "golden file " << path << " rewritten";
    ASSERT_TRUE(fs::exists(path)) << "missing golden file " << path << " (run with ESI_UPDATE_GOLDEN=1)";
    EXPECT_EQ(esi::test::read_text(path), actual)
        << "report differs from " << path << "; if intended, regenerate with ESI_UPDATE_GOLDEN=1";
}

TEST(DiffReport, TextMatchesGolden) { check_golden("text.txt", esi::render_diff_text(sample_result(), labels)); }

TEST(DiffReport, JsonMatchesGolden) { check_golden("json.json", esi::render_diff_json(sample_result())); }

TEST(DiffReport, MarkdownMatchesGolden) { check_golden("markdown.md", esi::render_diff_markdown(sample_result(), labels)); }

TEST(DiffReport, JsonHasExactlyTheIssueShape) {
    const auto j = nlohmann::json::parse(esi::render_diff_json(sample_result()));
    ASSERT_TRUE(j.is_object());
    EXPECT_EQ(j.size(), 2u);
    EXPECT_EQ(j.at("verdict"), "breaking");
    const std::set<std::string> verdicts{"identical", "cosmetic", "compatible", "breaking"};
    EXPECT_TRUE(verdicts.count(j.at("verdict").get<std::string>()));
    const std::set<std::string> keys{"device", "path", "kind", "class", "old", "new", "old_pos", "new_pos", "message"};
    ASSERT_FALSE(j.at("changes").empty());
    bool file_level = false;
    for (const auto& c : j.at("changes")) {
        std::set<std::string> seen;
        for (const auto& [k, v] : c.items()) seen.insert(k);
        EXPECT_EQ(seen, keys);
        if (c.at("device").is_null()) {
            file_level = true;
        } else {
            EXPECT_TRUE(c.at("device").at("name").is_string());
            EXPECT_TRUE(c.at("device").at("product_code").is_number_unsigned());  // a number, not "#x…"
            EXPECT_TRUE(c.at("device").at("revision").is_number_unsigned());
            EXPECT_EQ(c.at("device").size(), 3u);
        }
        EXPECT_TRUE(c.at("old").is_null() || c.at("old").is_string());
        EXPECT_TRUE(c.at("new").is_null() || c.at("new").is_string());
        for (const char* pos : {"old_pos", "new_pos"})
            if (!c.at(pos).is_null()) {
                EXPECT_GT(c.at(pos).at("line").get<int>(), 0);
                EXPECT_GT(c.at(pos).at("column").get<int>(), 0);
            }
        EXPECT_TRUE(std::set<std::string>({"breaking", "compatible", "cosmetic"}).count(c.at("class").get<std::string>()));
    }
    EXPECT_TRUE(file_level);
    EXPECT_EQ(j.at("changes").at(0).at("device").is_null(), true);  // file-level changes come first
    EXPECT_EQ(j.at("changes").at(1).at("device").at("product_code"), 0x1001);
}

TEST(DiffReport, IdenticalFilesSayIdenticalInEveryFormat) {
    const esi::FileDiff diff = esi::diff_files(data("old.xml"), data("old.xml"));
    ASSERT_TRUE(diff.result);
    EXPECT_EQ(esi::render_diff_text(*diff.result, {"a.xml", "b.xml"}), "a.xml -> b.xml: identical (no changes)\n");
    EXPECT_EQ(nlohmann::json::parse(esi::render_diff_json(*diff.result)),
              nlohmann::json::parse(R"({"verdict":"identical","changes":[]})"));
    EXPECT_NE(esi::render_diff_markdown(*diff.result, {"a.xml", "b.xml"}).find("identical"), std::string::npos);
}

TEST(DiffReport, MarkdownEscapesTableCells) {
    const std::string md = esi::render_diff_markdown(sample_result(), labels);
    // The vendor name in new.xml contains a pipe; it must not split the table row.
    EXPECT_NE(md.find("Example \\| Automation"), std::string::npos) << md;
}

TEST(DiffReport, RenderingIsByteIdenticalOnRerun) {
    const esi::DiffResult a = sample_result();
    const esi::DiffResult b = sample_result();
    EXPECT_EQ(esi::render_diff_text(a, labels), esi::render_diff_text(b, labels));
    EXPECT_EQ(esi::render_diff_json(a), esi::render_diff_json(b));
    EXPECT_EQ(esi::render_diff_markdown(a, labels), esi::render_diff_markdown(b, labels));
}

}  // namespace

#include "diff_fixture.hpp"

TEST(DiffReportText, LongOrMultiLineTextStaysOnOneShortLine) {
    const std::string long_text(500, 'x');
    const std::string old_xml =
        esi::test::edit(esi::test::diff_base, "</Electrical></Info>", "</Electrical><Note>a</Note></Info>");
    const std::string new_xml =
        esi::test::edit(esi::test::diff_base, "</Electrical></Info>", "</Electrical><Note>" + long_text + "</Note></Info>");
    const esi::DiffResult r = esi::test::diff_texts(old_xml, new_xml);
    ASSERT_EQ(r.changes.size(), 1u) << esi::test::describe(r);
    EXPECT_EQ(r.changes[0].new_value, long_text);  // the value itself is complete
    EXPECT_LT(r.changes[0].message.size(), 200u);  // the message quotes its start
    // Unmodelled text compares as written (same_content trims only the ends); a line break inside
    // it must not break the one-line-per-change text format.
    const std::string multi = esi::test::edit(new_xml, long_text, "first\nsecond");
    const std::string text = esi::render_diff_text(esi::test::diff_texts(old_xml, multi), {"a", "b"});
    EXPECT_NE(text.find("from 'a' to 'first second'"), std::string::npos) << text;
}
