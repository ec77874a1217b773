// esi-lint --fix and --diff (issue 22): the safe fixes applied to files or shown as a diff,
// and the rule catalogue saying which rules can fix.

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

TEST(EsiLintFix, StandardInputIsNotFixed) {
    EXPECT_EQ(run({tool("esi-lint"), "--fix", "-"}, read_text(findings())).exit_code, 2);
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
