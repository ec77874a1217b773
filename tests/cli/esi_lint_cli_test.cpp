// esi-lint as users and CI call it: exit codes, the four output formats, stdin, directories,
// the rule catalogue.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_support.hpp"

namespace {

using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string sample() { return (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string(); }
std::string findings() { return (esi::test::source_dir() / "tests" / "cli" / "data" / "findings.xml").string(); }
const char* malformed = "<EtherCATInfo>\n<Vendor>\n<Name>x</Name \n</Vendor></EtherCATInfo>\n";

TEST(EsiLintCli, CleanSampleExitsZero) {
    const auto r = run({tool("esi-lint"), sample()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("0 errors, 0 warnings, 0 infos in 1 file"), std::string::npos) << r.out;
}

TEST(EsiLintCli, WarningOnlyFileDependsOnFailOn) {
    EXPECT_EQ(run({tool("esi-lint"), findings(), "--no-source"}).exit_code, 0);
    EXPECT_EQ(run({tool("esi-lint"), findings(), "--fail-on", "warning"}).exit_code, 1);
    EXPECT_EQ(run({tool("esi-lint"), findings(), "--fail-on", "info"}).exit_code, 1);
    EXPECT_EQ(run({tool("esi-lint"), findings(), "--fail-on", "never"}).exit_code, 0);
}

TEST(EsiLintCli, TextFormatQuotesTheLine) {
    const auto r = run({tool("esi-lint"), findings()});
    EXPECT_NE(r.out.find("findings.xml:4:5: warning: Id: '0xF3F' uses the C prefix 0x; ESI hex numbers are written #x [xml-hex-prefix]"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("     4 |     <Id>0xF3F</Id>\n       |     ^\n"), std::string::npos) << r.out;
}

TEST(EsiLintCli, MalformedFileIsErrorExitOne) {
    TempDir dir;
    write_text(dir / "bad.xml", malformed);
    const auto r = run({tool("esi-lint"), (dir / "bad.xml").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.out.find("bad.xml:3:8: error: not well-formed"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("[xml-syntax]"), std::string::npos);
}

TEST(EsiLintCli, UnreadableInputAndUsageErrorsExitTwo) {
    EXPECT_EQ(run({tool("esi-lint"), "/nonexistent/x.xml"}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-lint")}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-lint"), "--format", "yaml", sample()}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-lint"), "--no-such-flag", sample()}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-lint"), "--explain", "no-such-rule"}).exit_code, 2);
}

TEST(EsiLintCli, BrokenConfigExitsTwoWithPosition) {
    TempDir dir;
    write_text(dir / "c.yaml", "rules:\n  xml-hex-prefx: off\n");
    const auto r = run({tool("esi-lint"), "--config", (dir / "c.yaml").string(), sample()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.out.find("c.yaml:2:3: error: unknown rule 'xml-hex-prefx'; did you mean 'xml-hex-prefix'?"), std::string::npos) << r.out;
}

TEST(EsiLintCli, NearestConfigIsUsed) {
    TempDir dir;
    write_text(dir / ".esi-lint.yaml", "rules:\n  xml-hex-prefix: error\n");
    write_text(dir / "sub" / "f.xml", esi::test::read_text(findings()));
    const auto r = run({tool("esi-lint"), (dir / "sub" / "f.xml").string()});
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find("error: Id: '0xF3F'"), std::string::npos) << r.out;
}

TEST(EsiLintCli, JsonFormat) {
    const auto r = run({tool("esi-lint"), "--format", "json", findings()});
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["diagnostics"].size(), 1u);
    const auto& d = j["diagnostics"][0];
    EXPECT_EQ(d["path"], findings());
    EXPECT_EQ(d["line"], 4);
    EXPECT_EQ(d["column"], 5);
    EXPECT_EQ(d["severity"], "warning");
    EXPECT_EQ(d["rule"], "xml-hex-prefix");
    EXPECT_EQ(j["summary"]["warnings"], 1);
    EXPECT_EQ(j["summary"]["files"], 1);
}

TEST(EsiLintCli, SarifFormatIsSarif210) {
    const auto r = run({tool("esi-lint"), "--format", "sarif", findings()});
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["version"], "2.1.0");
    const auto& run0 = j["runs"][0];
    EXPECT_EQ(run0["tool"]["driver"]["name"], "esi-lint");
    ASSERT_EQ(run0["results"].size(), 1u);
    const auto& result = run0["results"][0];
    EXPECT_EQ(result["ruleId"], "xml-hex-prefix");
    EXPECT_EQ(result["level"], "warning");
    const auto& region = result["locations"][0]["physicalLocation"]["region"];
    EXPECT_EQ(region["startLine"], 4);
    EXPECT_EQ(region["startColumn"], 5);
    const auto index = result["ruleIndex"].get<std::size_t>();
    EXPECT_EQ(run0["tool"]["driver"]["rules"][index]["id"], "xml-hex-prefix");
}

TEST(EsiLintCli, GithubAnnotations) {
    const auto r = run({tool("esi-lint"), "--format", "github", findings()});
    EXPECT_EQ(r.out, "::warning file=" + findings() +
                         ",line=4,col=5,title=xml-hex-prefix::Id: '0xF3F' uses the C prefix 0x; ESI hex numbers are written #x\n");
}

TEST(EsiLintCli, ReadsStdin) {
    const auto r = run({tool("esi-lint"), "-", "--no-source"}, malformed);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.out.find("<stdin>:3:8: error:"), std::string::npos) << r.out;
}

TEST(EsiLintCli, DirectoriesAreRecursiveAndSorted) {
    TempDir dir;
    write_text(dir / "b" / "z.xml", malformed);
    write_text(dir / "a.xml", malformed);
    write_text(dir / "notes.txt", "ignored");
    const auto r = run({tool("esi-lint"), "--format", "json", "-j", "4", dir.path().string()});
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["diagnostics"].size(), 2u);
    EXPECT_EQ(j["diagnostics"][0]["path"], (dir / "a.xml").string());
    EXPECT_EQ(j["diagnostics"][1]["path"], (dir / "b" / "z.xml").string());
    EXPECT_EQ(j["summary"]["files"], 2);
}

TEST(EsiLintCli, InlineSuppression) {
    TempDir dir;
    std::string text = esi::test::read_text(findings());
    text.replace(text.find("    <Id>"), 0, "    <!-- esi-lint: disable-next-line=xml-hex-prefix -->\n");
    write_text(dir / "f.xml", text);
    const auto r = run({tool("esi-lint"), "--fail-on", "info", (dir / "f.xml").string()});
    EXPECT_EQ(r.exit_code, 0) << r.out;
}

TEST(EsiLintCli, RuleCatalogue) {
    const auto text = run({tool("esi-lint"), "--list-rules"});
    EXPECT_EQ(text.exit_code, 0);
    EXPECT_NE(text.out.find("xml-syntax"), std::string::npos);
    const auto json = run({tool("esi-lint"), "--list-rules", "--format", "json"});
    const auto j = nlohmann::json::parse(json.out);
    EXPECT_GE(j["rules"].size(), 10u);
    for (const auto& rule : j["rules"]) {
        EXPECT_FALSE(rule["rationale"].get<std::string>().empty());
        EXPECT_FALSE(rule["bad_example"].get<std::string>().empty());
    }
    const auto explain = run({tool("esi-lint"), "--explain", "xml-hex-prefix"});
    EXPECT_EQ(explain.exit_code, 0);
    EXPECT_NE(explain.out.find("Bad:"), std::string::npos);
    EXPECT_NE(explain.out.find("<Id>0xF3F</Id>"), std::string::npos);
}

TEST(EsiLintCli, XsdValidationReportsSchemaErrors) {
    if (!esi::test::have_shared_corpus()) GTEST_SKIP() << "../shared/corpus not present: schema files missing";
    const auto xsd = (esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022").string();
    const auto r = run({tool("esi-lint"), "--xsd", xsd, "--format", "json", findings()});
    const auto j = nlohmann::json::parse(r.out);
    bool schema = false;
    for (const auto& d : j["diagnostics"]) schema = schema || d["rule"] == "xml-schema";
    EXPECT_TRUE(schema) << r.out;
    EXPECT_EQ(run({tool("esi-lint"), "--xsd", xsd, sample()}).exit_code, 0);
}

}  // namespace
