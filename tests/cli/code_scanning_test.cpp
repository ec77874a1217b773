// esi-lint's reports for code-scanning services (issue 14, items 5 and 7): SARIF as GitHub code
// scanning and the SARIF multitool want it, and GitLab's Code Quality report.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <map>
#include <set>
#include <nlohmann/json.hpp>

#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string findings_text() { return read_text(esi::test::source_dir() / "tests" / "cli" / "data" / "findings.xml"); }

// A checkout: repo/devices/f.xml holds one xml-hex-prefix finding.
struct Checkout {
    TempDir dir;
    Checkout() { write_text(dir / "devices" / "f.xml", findings_text()); }
    [[nodiscard]] fs::path root() const { return dir.path(); }
    [[nodiscard]] json lint(std::vector<std::string> args, const std::string& format = "sarif") const {
        args.insert(args.begin(), {tool("esi-lint").string(), "--format", format});
        const auto r = run(args, {}, root());
        return json::parse(r.out);
    }
};

// The official SARIF multitool (npm @microsoft/sarif-multitool-linux), or empty.
std::string sarif_multitool() {
    std::vector<std::string> candidates;
    if (const char* given = std::getenv("ESI_SARIF_MULTITOOL")) candidates.emplace_back(given);
    for (const char* prefix : {"/usr/lib/node_modules", "/usr/local/lib/node_modules"})
        candidates.push_back(std::string(prefix) + "/@microsoft/sarif-multitool-linux/Sarif.Multitool");
    for (const auto& c : candidates)
        if (::access(c.c_str(), X_OK) == 0) return c;
    return {};
}

}  // namespace

TEST(Sarif, UrisAreRelativeToTheSourceRoot) {
    Checkout checkout;
    for (const std::string& given : {std::string("devices/f.xml"), (checkout.root() / "devices" / "f.xml").string()}) {
        const json sarif = checkout.lint({given});
        const auto& run0 = sarif["runs"][0];
        const auto& artifact = run0["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"];
        EXPECT_EQ(artifact["uri"], "devices/f.xml") << given;
        EXPECT_EQ(artifact["uriBaseId"], "%SRCROOT%");
        const std::string base = run0["originalUriBaseIds"]["%SRCROOT%"]["uri"];
        EXPECT_EQ(base, "file://" + fs::canonical(checkout.root()).string() + "/");
    }
}

TEST(Sarif, AFileOutsideTheRootHasAnAbsoluteFileUri) {
    Checkout checkout;
    TempDir elsewhere;
    write_text(elsewhere / "g.xml", findings_text());
    const json sarif = checkout.lint({(elsewhere / "g.xml").string()});
    const auto& artifact = sarif["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"];
    EXPECT_EQ(artifact["uri"], "file://" + (elsewhere / "g.xml").string());
    EXPECT_FALSE(artifact.contains("uriBaseId"));
}

TEST(Sarif, ReadAndConfigErrorsAreToolNotificationsNotResults) {
    Checkout checkout;
    const json missing = checkout.lint({"devices/f.xml", "devices/missing.xml"});
    const auto& run0 = missing["runs"][0];
    ASSERT_EQ(run0["results"].size(), 1u);
    EXPECT_EQ(run0["results"][0]["ruleId"], "xml-hex-prefix");
    const auto& invocation = run0["invocations"][0];
    EXPECT_FALSE(invocation["executionSuccessful"].get<bool>());
    ASSERT_EQ(invocation["toolExecutionNotifications"].size(), 1u);
    const auto& note = invocation["toolExecutionNotifications"][0];
    EXPECT_EQ(note["descriptor"]["id"], "io-error");
    EXPECT_EQ(note["level"], "error");
    EXPECT_EQ(note["locations"][0]["physicalLocation"]["artifactLocation"]["uri"], "devices/missing.xml");

    write_text(checkout.root() / ".esi-lint.yaml", "rules:\n  xml-hex-prefx: off\n");
    const json config = checkout.lint({"devices/f.xml"});
    const auto& notes = config["runs"][0]["invocations"][0]["toolExecutionNotifications"];
    ASSERT_EQ(notes.size(), 1u) << config.dump(2);
    EXPECT_NE(notes[0]["message"]["text"].get<std::string>().find("xml-hex-prefx"), std::string::npos);
    EXPECT_EQ(notes[0]["locations"][0]["physicalLocation"]["region"]["startLine"], 2);
    for (const auto& result : config["runs"][0]["results"]) EXPECT_NE(result["ruleId"], "yaml-unknown-key");

    fs::remove(checkout.root() / ".esi-lint.yaml");
    const json ok = checkout.lint({"devices/f.xml"});
    EXPECT_TRUE(ok["runs"][0]["invocations"][0]["executionSuccessful"].get<bool>());
    EXPECT_FALSE(ok["runs"][0]["invocations"][0].contains("toolExecutionNotifications"));
}

TEST(Sarif, HelpUrisPointAtTheRulesSectionWhenTheDocsAddressIsGiven) {
    Checkout checkout;
    const std::string docs = "https://example.org/libesi/docs/rules.md";
    const json with = checkout.lint({"--sarif-help-base", docs, "devices/f.xml"});
    const auto& driver = with["runs"][0]["tool"]["driver"];
    const auto index = with["runs"][0]["results"][0]["ruleIndex"].get<std::size_t>();
    EXPECT_EQ(driver["rules"][index]["helpUri"], docs + "#xml-hex-prefix");
    EXPECT_EQ(driver["informationUri"], docs);
    // The fragment is the rule's heading anchor in docs/rules.md.
    const std::string rules_md = read_text(esi::test::source_dir() / "docs" / "rules.md");
    for (const auto& rule : driver["rules"])
        EXPECT_NE(rules_md.find("\n## " + rule["id"].get<std::string>() + "\n"), std::string::npos) << rule["id"];

    const json without = checkout.lint({"devices/f.xml"});
    EXPECT_FALSE(without["runs"][0]["tool"]["driver"]["rules"][index].contains("helpUri"));
    EXPECT_FALSE(without["runs"][0]["tool"]["driver"].contains("informationUri"));
}

TEST(Sarif, FingerprintsSurviveLinesAddedAbove) {
    Checkout checkout;
    const json before = checkout.lint({"devices/f.xml"});
    std::string shifted = findings_text();
    shifted.insert(shifted.find("<EtherCATInfo>"), "<!-- a new comment\n     over two lines -->\n");
    write_text(checkout.root() / "devices" / "f.xml", shifted);
    const json after = checkout.lint({"devices/f.xml"});
    const auto& a = before["runs"][0]["results"][0];
    const auto& b = after["runs"][0]["results"][0];
    EXPECT_EQ(b["locations"][0]["physicalLocation"]["region"]["startLine"], 6);
    ASSERT_TRUE(a["partialFingerprints"].contains("esiLint/v1"));
    EXPECT_EQ(a["partialFingerprints"], b["partialFingerprints"]);

    std::string edited = findings_text();
    edited.replace(edited.find("0xF3F"), 5, "0xF40");
    write_text(checkout.root() / "devices" / "f.xml", edited);
    const json changed = checkout.lint({"devices/f.xml"});
    EXPECT_NE(changed["runs"][0]["results"][0]["partialFingerprints"], a["partialFingerprints"]) << "the line itself changed";
}

TEST(Sarif, TheOfficialMultitoolFindsNothingToReport) {
    const std::string multitool = sarif_multitool();
    if (multitool.empty())
        GTEST_SKIP() << "SARIF multitool not installed (npm install -g @microsoft/sarif-multitool-linux, or set "
                        "ESI_SARIF_MULTITOOL): the official schema and rule check is skipped";
    Checkout checkout;
    write_text(checkout.root() / "devices" / "bad.xml", "<EtherCATInfo><Vendor>\n");
    const auto lint = run({tool("esi-lint").string(), "--format", "sarif", "--sarif-help-base", "https://example.org/rules.md",
                           "devices/f.xml", "devices/bad.xml", "devices/missing.xml"},
                          {}, checkout.root());
    write_text(checkout.root() / "out.sarif", lint.out);
    const auto validate = run({multitool, "validate", "out.sarif", "-o", "validation.sarif"}, {}, checkout.root());
    ASSERT_EQ(validate.exit_code, 0) << validate.out << validate.err;
    const json log = json::parse(read_text(checkout.root() / "validation.sarif"));
    std::string problems;
    for (const auto& r : log["runs"][0]["results"])
        if (r.value("level", "warning") != "note") problems += r["ruleId"].get<std::string>() + ": " + r["message"].dump() + "\n";
    EXPECT_EQ(problems, "") << validate.out;
}

TEST(GitlabCodeQuality, IssuesHaveTheShapeGitlabReads) {
    Checkout checkout;
    write_text(checkout.root() / "devices" / "bad.xml", "<EtherCATInfo><Vendor>\n");
    const json issues = checkout.lint({"devices", "missing.xml"}, "gitlab");
    ASSERT_TRUE(issues.is_array());
    ASSERT_EQ(issues.size(), 3u) << issues.dump(2);
    std::set<std::string> fingerprints;
    std::map<std::string, std::string> severity_of;
    for (const auto& issue : issues) {
        for (const char* key : {"description", "check_name", "fingerprint", "severity"}) EXPECT_TRUE(issue[key].is_string()) << key;
        EXPECT_TRUE(issue["location"]["path"].is_string());
        EXPECT_GE(issue["location"]["lines"]["begin"].get<int>(), 1);
        fingerprints.insert(issue["fingerprint"].get<std::string>());
        severity_of[issue["check_name"].get<std::string>() + " " + issue["location"]["path"].get<std::string>()] = issue["severity"];
    }
    EXPECT_EQ(fingerprints.size(), issues.size()) << "fingerprints are unique";
    EXPECT_EQ(severity_of["xml-hex-prefix devices/f.xml"], "minor");
    EXPECT_EQ(severity_of["xml-syntax devices/bad.xml"], "major");
    EXPECT_EQ(severity_of["io-error missing.xml"], "blocker");
}
