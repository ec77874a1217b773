// Adopting esi-lint on an existing catalogue (issue 22): a baseline of the findings it already
// has, counts per rule, and files left out of directory walks.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string findings() { return (esi::test::source_dir() / "tests" / "cli" / "data" / "findings.xml").string(); }
std::string sample_xml() { return (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string(); }

// findings.xml with `Id` written 0xF3F (xml-hex-prefix) on line 4; `extra` lines above it move it down.
std::string with_lines_above(int extra) {
    std::string text = read_text(findings());
    const auto after_declaration = text.find('\n') + 1;
    for (int i = 0; i < extra; ++i) text.insert(after_declaration, "<!-- a comment added later -->\n");
    return text;
}

TEST(EsiLintAdoption, ABaselineHidesTheFindingsItHoldsEvenAfterLinesMove) {
    TempDir dir;
    write_text(dir / "f.xml", with_lines_above(0));
    const auto written = run({tool("esi-lint"), "--fail-on", "warning", "--write-baseline", "baseline.json", "f.xml"}, {}, dir.path());
    EXPECT_EQ(written.exit_code, 0) << written.out << written.err;
    const auto baseline = nlohmann::json::parse(read_text(dir / "baseline.json"));
    ASSERT_EQ(baseline["findings"].size(), 1u) << baseline.dump();
    EXPECT_EQ(baseline["findings"][0]["rule"], "xml-hex-prefix");
    EXPECT_EQ(baseline["findings"][0]["path"], "f.xml");

    write_text(dir / "f.xml", with_lines_above(3));
    const auto r = run({tool("esi-lint"), "--fail-on", "warning", "--baseline", "baseline.json", "f.xml"}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("[xml-hex-prefix]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0 errors, 0 warnings, 0 infos in 1 file (1 finding in the baseline)"), std::string::npos) << r.out;
}

TEST(EsiLintAdoption, AFindingOnAnEditedLineIsNew) {
    TempDir dir;
    write_text(dir / "f.xml", with_lines_above(0));
    ASSERT_EQ(run({tool("esi-lint"), "--write-baseline", "baseline.json", "f.xml"}, {}, dir.path()).exit_code, 0);
    std::string text = with_lines_above(0);
    const auto id = text.find("<Id>0xF3F</Id>");
    ASSERT_NE(id, std::string::npos);
    text.replace(id, 14, "<Id>0xF3E</Id>");
    write_text(dir / "f.xml", text);
    const auto r = run({tool("esi-lint"), "--fail-on", "warning", "--baseline", "baseline.json", "f.xml"}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("'0xF3E'"), std::string::npos) << r.out;
}

TEST(EsiLintAdoption, ABrokenBaselineIsAUsageError) {
    TempDir dir;
    write_text(dir / "b.json", "{\"findings\": []}");
    const auto r = run({tool("esi-lint"), "--baseline", (dir / "b.json").string(), sample_xml()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("not an esi-lint baseline"), std::string::npos) << r.err;
    EXPECT_EQ(run({tool("esi-lint"), "--baseline", (dir / "missing.json").string(), sample_xml()}).exit_code, 2);
}

TEST(EsiLintAdoption, StatisticsCountPerRuleAndSeverity) {
    TempDir dir;
    write_text(dir / "a.xml", with_lines_above(0));
    write_text(dir / "b.xml", with_lines_above(1));
    write_text(dir / ".esi-lint.yaml", "overrides:\n  - files: [b.xml]\n    rules: { xml-hex-prefix: error }\n");
    const auto r = run({tool("esi-lint"), "--statistics", dir.path().string()});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // b.xml's finding is an error
    EXPECT_NE(r.out.find("     1  error    xml-hex-prefix  "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("     1  warning  xml-hex-prefix  "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("2 findings in 2 files\n"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("f.xml:"), std::string::npos) << "statistics replace the findings: " << r.out;

    const auto j = nlohmann::json::parse(run({tool("esi-lint"), "--statistics", "--format", "json", dir.path().string()}).out);
    ASSERT_EQ(j["statistics"].size(), 2u) << j.dump();
    EXPECT_EQ(j["statistics"][0]["severity"], "error");
    EXPECT_EQ(j["statistics"][0]["count"], 1);
    EXPECT_EQ(run({tool("esi-lint"), "--statistics", "--format", "sarif", dir.path().string()}).exit_code, 2);
}

TEST(EsiLintAdoption, ExcludeGlobsInTheConfigAndOnTheCommandLine) {
    TempDir dir;
    write_text(dir / "new" / "a.xml", read_text(sample_xml()));
    write_text(dir / "legacy" / "old" / "b.xml", with_lines_above(0));
    write_text(dir / "c.xml", with_lines_above(0));
    write_text(dir / ".esi-lint.yaml", "exclude: [legacy]\n");
    auto r = run({tool("esi-lint"), "--fail-on", "warning", "."}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.out;  // c.xml
    EXPECT_EQ(r.out.find("b.xml"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("in 2 files (1 excluded)"), std::string::npos) << r.out;

    r = run({tool("esi-lint"), "--fail-on", "warning", "--exclude", "c.xml", "."}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("in 1 file (2 excluded)"), std::string::npos) << r.out;

    // A file named on the command line is linted whatever the globs say.
    r = run({tool("esi-lint"), "--fail-on", "warning", "--exclude", "c.xml", "c.xml"}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.out;
}

TEST(EsiLintAdoption, AnExcludeThatIsNotAListIsAConfigError) {
    TempDir dir;
    write_text(dir / ".esi-lint.yaml", "exclude: { a: b }\n");
    write_text(dir / "c.xml", read_text(sample_xml()));
    const auto r = run({tool("esi-lint"), "."}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find(".esi-lint.yaml:1:10: error:"), std::string::npos) << r.out;
}

}  // namespace
