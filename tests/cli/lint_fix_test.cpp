// esi-lint --fix and --diff (issue 22): the safe fixes applied to files or shown as a diff,
// and the rule catalogue saying which rules can fix.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <map>

#include "support/test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string findings() { return (esi::test::source_dir() / "tests" / "cli" / "data" / "findings.xml").string(); }

std::string fixed_findings() {
    std::string text = read_text(findings());
    text.replace(text.find("0xF3F"), 2, "#x");
    return text;
}

TEST(EsiLintFix, FixRewritesTheFileAndReportsWhatIsLeft) {
    TempDir dir;
    write_text(dir / "f.xml", read_text(findings()));
    const auto r = run({tool("esi-lint"), "--fix", "--fail-on", "warning", (dir / "f.xml").string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.err.find("fixed 1 finding in 1 file"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("[xml-hex-prefix]"), std::string::npos) << r.out;
    EXPECT_EQ(read_text(dir / "f.xml"), fixed_findings());
    // A second run has nothing left to fix.
    const auto again = run({tool("esi-lint"), "--fix", (dir / "f.xml").string()});
    EXPECT_NE(again.err.find("fixed 0 findings in 0 files"), std::string::npos) << again.err;
}

TEST(EsiLintFix, DiffShowsTheFixAndWritesNothing) {
    TempDir dir;
    write_text(dir / "f.xml", read_text(findings()));
    const auto r = run({tool("esi-lint"), "--diff", "f.xml"}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("--- a/f.xml\n+++ b/f.xml\n@@ -1,7 +1,7 @@\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n-    <Id>0xF3F</Id>\n+    <Id>#xF3F</Id>\n"), std::string::npos) << r.out;
    EXPECT_EQ(read_text(dir / "f.xml"), read_text(findings()));

    write_text(dir / "f.xml", fixed_findings());
    const auto clean = run({tool("esi-lint"), "--diff", "f.xml"}, {}, dir.path());
    EXPECT_EQ(clean.exit_code, 0) << clean.out << clean.err;
    EXPECT_EQ(clean.out, "");
}

TEST(EsiLintFix, StandardInputIsFixedToStandardOutput) {
    TempDir dir;  // no .esi-lint.yaml above it
    const auto r = run({tool("esi-lint"), "--fix", "--fail-on", "warning", "-"}, read_text(findings()), dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, fixed_findings());
    EXPECT_NE(r.err.find("fixed 1 finding in <stdin>"), std::string::npos) << r.err;

    // What cannot be fixed is left in the output as it was and reported on stderr, with its exit code.
    std::string unfixable = read_text(findings());
    unfixable.replace(unfixable.find("0xF3F"), 5, "12h");
    const auto left = run({tool("esi-lint"), "--fix", "-"}, unfixable, dir.path());
    EXPECT_EQ(left.exit_code, 1) << left.err;
    EXPECT_EQ(left.out, unfixable);
    EXPECT_NE(left.err.find("<stdin>:4:5: error: "), std::string::npos) << left.err;
    EXPECT_NE(left.err.find("[xml-number-format]"), std::string::npos) << left.err;
}

TEST(EsiLintFix, StandardInputDiff) {
    TempDir dir;
    const auto r = run({tool("esi-lint"), "--diff", "-"}, read_text(findings()), dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.out.find("--- a/<stdin>\n+++ b/<stdin>\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n-    <Id>0xF3F</Id>\n+    <Id>#xF3F</Id>\n"), std::string::npos) << r.out;
    const auto clean = run({tool("esi-lint"), "--diff", "-"}, fixed_findings(), dir.path());
    EXPECT_EQ(clean.exit_code, 0) << clean.err;
    EXPECT_EQ(clean.out, "");
}

TEST(EsiLintFix, StandardInputGoesAlone) {
    TempDir dir;
    write_text(dir / "f.xml", read_text(findings()));
    const auto r = run({tool("esi-lint"), "--fix", "-", "f.xml"}, read_text(findings()), dir.path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("standard input alone"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(dir / "f.xml"), read_text(findings())) << "nothing is written";
}

TEST(EsiLintFix, DiffOfTheRemovingFixes) {
    // An obsolete attribute, a repeated OpMode and an undeclared xsi: prefix, in one diff.
    std::string text = read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml");
    const std::string declaration = " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"";
    text.erase(text.find(declaration), declaration.size());
    text.replace(text.find("DefaultSize=\"128\""), 17, "DefaultSize=\"128\" OneByteMode=\"false\"");
    const auto op_mode = text.find("          <OpMode>");
    const auto op_mode_end = text.find("</OpMode>\n", op_mode) + 10;
    const std::string copy = text.substr(op_mode, op_mode_end - op_mode);
    text.insert(op_mode_end, copy);
    TempDir dir;
    write_text(dir / "f.xml", text);
    const auto r = run({tool("esi-lint"), "--diff", "f.xml"}, {}, dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.err.find("3 fixable findings in 1 file"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("\n-<EtherCATInfo xsi:noNamespaceSchemaLocation=\"EtherCATInfo.xsd\" Version=\"1.17\">\n"
                         "+<EtherCATInfo" + declaration + " xsi:noNamespaceSchemaLocation=\"EtherCATInfo.xsd\" Version=\"1.17\">\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\n-        <Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" OneByteMode=\"false\" MinSize="),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\n+        <Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" MinSize="), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\n-          <OpMode>\n"), std::string::npos) << r.out;
    // Applied, the file lints as the sample does: nothing to fix, nothing found.
    const auto fixed = run({tool("esi-lint"), "--fix", "f.xml"}, {}, dir.path());
    EXPECT_EQ(fixed.exit_code, 0) << fixed.out << fixed.err;
    const auto after = run({tool("esi-lint"), "--fail-on", "info", "f.xml"}, {}, dir.path());
    EXPECT_EQ(after.exit_code, 0) << after.out;
}

TEST(EsiLintFix, SarifCarriesTheFixes) {
    TempDir dir;
    std::string text = read_text(findings());
    text.replace(text.find("<EtherCATInfo>"), 14, "<EtherCATInfo xsi:noNamespaceSchemaLocation=\"EtherCATInfo.xsd\">");
    write_text(dir / "f.xml", text);
    const auto r = run({tool("esi-lint"), "--format", "sarif", "f.xml"}, {}, dir.path());
    const auto sarif = nlohmann::json::parse(r.out);
    std::map<std::string, nlohmann::json> fixes;
    for (const auto& result : sarif["runs"][0]["results"])
        if (result.contains("fixes")) fixes[result["ruleId"].get<std::string>()] = result["fixes"];
    ASSERT_EQ(fixes.size(), 2u) << r.out;

    // 0x → #x on line 4, columns 9-11 (code points, the run's columnKind).
    const auto& hex = fixes["xml-hex-prefix"][0];
    EXPECT_EQ(hex["description"]["text"], "write #x for 0x");
    const auto& change = hex["artifactChanges"][0];
    EXPECT_EQ(change["artifactLocation"]["uri"], "f.xml");
    EXPECT_EQ(change["replacements"][0]["deletedRegion"],
              nlohmann::json({{"startLine", 4}, {"startColumn", 9}, {"endLine", 4}, {"endColumn", 11}}));
    EXPECT_EQ(change["replacements"][0]["insertedContent"]["text"], "#x");

    // The declaration: an insertion, an empty region right after the root's name.
    const auto& xsi = fixes["xml-undeclared-prefix"][0]["artifactChanges"][0]["replacements"][0];
    EXPECT_EQ(xsi["deletedRegion"], nlohmann::json({{"startLine", 2}, {"startColumn", 14}, {"endLine", 2}, {"endColumn", 14}}));
    EXPECT_EQ(xsi["insertedContent"]["text"], " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"");
}

TEST(EsiLintFix, TheCatalogueMarksFixableRules) {
    const auto text = run({tool("esi-lint"), "--list-rules"});
    bool hex = false;
    bool syntax = false;
    std::size_t start = 0;
    for (std::size_t end; (end = text.out.find('\n', start)) != std::string::npos; start = end + 1) {
        const std::string line = text.out.substr(start, end - start);
        if (line.starts_with("xml-hex-prefix ")) hex = line.find("[*]") != std::string::npos;
        if (line.starts_with("xml-syntax ")) syntax = line.find("[*]") != std::string::npos;
        for (const char* fixable : {"deprecated-sm-one-byte-mode ", "deprecated-obsolete ", "dc-opmode-duplicate ",
                                    "pdo-duplicate-index ", "od-duplicate-object ", "xml-undeclared-prefix "})
            if (line.starts_with(fixable)) {
                EXPECT_NE(line.find("[*]"), std::string::npos) << line;
            }
    }
    EXPECT_TRUE(hex) << text.out;
    EXPECT_FALSE(syntax) << text.out;
    const auto j = nlohmann::json::parse(run({tool("esi-lint"), "--list-rules", "--format", "json"}).out);
    for (const auto& rule : j["rules"]) {
        if (rule["id"] == "xml-hex-prefix") {
            EXPECT_TRUE(rule["fix"].is_string());
        } else if (rule["id"] == "xml-syntax") {
            EXPECT_TRUE(rule["fix"].is_null());
        }
    }
    EXPECT_NE(run({tool("esi-lint"), "--explain", "xml-hex-prefix"}).out.find("Fix (--fix): "), std::string::npos);
}

}  // namespace
