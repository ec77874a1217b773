// esi-diff as users and CI call it: the interface of issue 4 §1, exit codes 0/1/2, formats,
// --fail-on, --device, and malformed input reported with its xml-syntax position.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_support.hpp"

namespace {

using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string data(const std::string& name) { return (esi::test::source_dir() / "tests" / "diff" / "data" / name).string(); }

TEST(EsiDiffCli, IdenticalFilesExitZero) {
    const auto r = run({tool("esi-diff"), data("old.xml"), data("old.xml")});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("identical (no changes)"), std::string::npos) << r.out;
    EXPECT_EQ(run({tool("esi-diff"), "--fail-on", "any", data("old.xml"), data("old.xml")}).exit_code, 0);
}

TEST(EsiDiffCli, BreakingChangeExitsOneByDefault) {
    const auto r = run({tool("esi-diff"), data("old.xml"), data("new.xml")});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("breaking"), std::string::npos);
    EXPECT_NE(r.out.find("[revision-not-changed]"), std::string::npos);
}

TEST(EsiDiffCli, FailOnDecidesTheExitCode) {
    EXPECT_EQ(run({tool("esi-diff"), "--fail-on", "never", data("old.xml"), data("new.xml")}).exit_code, 0);
    EXPECT_EQ(run({tool("esi-diff"), "--fail-on", "breaking", data("old.xml"), data("new.xml")}).exit_code, 1);

    // A cosmetic-only change: 0 for breaking, 1 for any.
    TempDir dir;
    std::string text = esi::test::read_text(data("old.xml"));
    const auto at = text.find("Beispielgerät");
    text.replace(at, std::string("Beispielgerät").size(), "Beispiel");
    write_text(dir / "cosmetic.xml", text);
    const auto cosmetic = run({tool("esi-diff"), data("old.xml"), (dir / "cosmetic.xml").string()});
    EXPECT_EQ(cosmetic.exit_code, 0) << cosmetic.out;
    EXPECT_NE(cosmetic.out.find(": cosmetic (1 cosmetic)"), std::string::npos) << cosmetic.out;
    EXPECT_EQ(run({tool("esi-diff"), "--fail-on", "any", data("old.xml"), (dir / "cosmetic.xml").string()}).exit_code, 1);
}

TEST(EsiDiffCli, JsonAndMarkdownFormats) {
    const auto j = run({tool("esi-diff"), "--format", "json", data("old.xml"), data("new.xml")});
    EXPECT_EQ(j.exit_code, 1);
    const auto parsed = nlohmann::json::parse(j.out);
    EXPECT_EQ(parsed.at("verdict"), "breaking");
    EXPECT_FALSE(parsed.at("changes").empty());

    const auto md = run({tool("esi-diff"), "--format", "markdown", data("old.xml"), data("new.xml")});
    EXPECT_EQ(md.exit_code, 1);
    EXPECT_EQ(md.out.rfind("### esi-diff: breaking", 0), 0u) << md.out;
}

TEST(EsiDiffCli, DeviceSelectorAcceptsDecimalAndHexWithRevision) {
    const auto hash = run({tool("esi-diff"), "--device", "#x2002", "--format", "json", data("old.xml"), data("new.xml")});
    const auto c_hex =
        run({tool("esi-diff"), "--device", "0x2002:0x20000", "--format", "json", data("old.xml"), data("new.xml")});
    const auto decimal = run({tool("esi-diff"), "--device", "8194", "--format", "json", data("old.xml"), data("new.xml")});
    EXPECT_EQ(hash.out, c_hex.out);
    EXPECT_EQ(hash.out, decimal.out);
    const auto parsed = nlohmann::json::parse(hash.out);
    ASSERT_FALSE(parsed.at("changes").empty());
    for (const auto& c : parsed.at("changes")) EXPECT_EQ(c.at("device").at("product_code"), 0x2002);
    // The second device only has a bumped revision and a changed SM size: breaking, but no revision error.
    EXPECT_EQ(hash.exit_code, 1);
    EXPECT_EQ(hash.out.find("revision-not-changed"), std::string::npos);
}

TEST(EsiDiffCli, UsageErrorsExitTwo) {
    EXPECT_EQ(run({tool("esi-diff")}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-diff"), data("old.xml")}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-diff"), "--format", "yaml", data("old.xml"), data("new.xml")}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-diff"), "--fail-on", "warning", data("old.xml"), data("new.xml")}).exit_code, 2);
    const auto bad_device = run({tool("esi-diff"), "--device", "12:zz", data("old.xml"), data("new.xml")});
    EXPECT_EQ(bad_device.exit_code, 2);
    EXPECT_NE(bad_device.err.find("revision"), std::string::npos) << bad_device.err;
    const auto no_match = run({tool("esi-diff"), "--device", "#x9999", data("old.xml"), data("new.xml")});
    EXPECT_EQ(no_match.exit_code, 2);
    EXPECT_NE(no_match.err.find("matches no device"), std::string::npos) << no_match.err;
}

TEST(EsiDiffCli, MissingOrMalformedInputExitsTwoWithPosition) {
    const auto missing = run({tool("esi-diff"), "/nonexistent/old.xml", data("new.xml")});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("[io-error]"), std::string::npos) << missing.err;

    TempDir dir;
    write_text(dir / "bad.xml", "<EtherCATInfo>\n<Vendor>\n<Name>x</Name \n</Vendor></EtherCATInfo>\n");
    const auto bad = run({tool("esi-diff"), data("old.xml"), (dir / "bad.xml").string()});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("bad.xml:3:8: error: not well-formed"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("[xml-syntax]"), std::string::npos);
    EXPECT_TRUE(bad.out.empty()) << bad.out;

    write_text(dir / "other.xml", "<Catalogue/>\n");
    EXPECT_EQ(run({tool("esi-diff"), (dir / "other.xml").string(), data("new.xml")}).exit_code, 2);
}

}  // namespace

namespace {

TEST(EsiDiffCli, IgnoreAndOnlyNarrowTheReportAndTheVerdict) {
    // old.xml -> new.xml has breaking changes and others.
    const auto all = run({tool("esi-diff"), "--format", "json", data("old.xml"), data("new.xml")});
    const auto all_changes = nlohmann::json::parse(all.out).at("changes");
    std::size_t breaking = 0, cosmetic = 0;
    for (const auto& c : all_changes) {
        breaking += c.at("class") == "breaking";
        cosmetic += c.at("class") == "cosmetic";
    }
    ASSERT_GT(breaking, 0u);
    ASSERT_LT(breaking, all_changes.size());

    const auto only = run({tool("esi-diff"), "--format", "json", "--only", "breaking", data("old.xml"), data("new.xml")});
    EXPECT_EQ(only.exit_code, 1) << only.err;
    const auto only_changes = nlohmann::json::parse(only.out).at("changes");
    EXPECT_EQ(only_changes.size(), breaking);
    for (const auto& c : only_changes) EXPECT_EQ(c.at("class"), "breaking");

    const auto ignored = run({tool("esi-diff"), "--format", "json", "--ignore", "cosmetic", data("old.xml"), data("new.xml")});
    EXPECT_EQ(nlohmann::json::parse(ignored.out).at("changes").size(), all_changes.size() - cosmetic);

    // A cosmetic-only change ignored is no change: identical, and --fail-on any passes.
    TempDir dir;
    std::string text = esi::test::read_text(data("old.xml"));
    const auto at = text.find("Beispielgerät");
    text.replace(at, std::string("Beispielgerät").size(), "Beispiel");
    write_text(dir / "cosmetic.xml", text);
    const auto hidden = run({tool("esi-diff"), "--fail-on", "any", "--ignore", "cosmetic", data("old.xml"), (dir / "cosmetic.xml").string()});
    EXPECT_EQ(hidden.exit_code, 0) << hidden.out;
    EXPECT_NE(hidden.out.find("identical"), std::string::npos) << hidden.out;

    // The two exclude each other; an unknown class is a usage error.
    EXPECT_EQ(run({tool("esi-diff"), "--only", "breaking", "--ignore", "cosmetic", data("old.xml"), data("new.xml")}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-diff"), "--ignore", "pretty", data("old.xml"), data("new.xml")}).exit_code, 2);
}

TEST(EsiDiffCli, PathsInsideTheCurrentDirectoryArePrintedRelative) {
    const std::string data_dir = (esi::test::source_dir() / "tests" / "diff" / "data").string();
    const auto r = run({"/bin/sh", "-c", "cd '" + data_dir + "' && '" + tool("esi-diff").string() + "' '" + data("old.xml") + "' '" +
                                             data("new.xml") + "'"});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.out.find("old.xml"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find(data_dir), std::string::npos) << r.out;
}

}  // namespace
