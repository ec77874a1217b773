// esi-doc as a user runs it: what it writes, exit codes, and that a failed run leaves the output
// directory as it was.

#include <gtest/gtest.h>

#include "doc_test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;
using namespace esi::test::doc;

TEST(EsiDocCli, WritesTheIndexAndAPagePerDeviceAndExitsZero) {
    TempDir dir;
    const auto r = esi_doc(esi::test::source_dir() / "tests" / "diff" / "data" / "old.xml", dir / "out");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = tree(dir / "out");
    std::vector<std::string> names;
    for (const auto& [name, content] : files) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"EX-1001-rev00010000.html", "EX-2002-rev00010000.html", "index.html"}));
}

TEST(EsiDocCli, TwoRunsAreByteIdentical) {
    TempDir a, b;
    ASSERT_EQ(esi_doc(samples_dir() / "modular-coupler.yaml", a / "out").exit_code, 0);
    ASSERT_EQ(esi_doc(samples_dir() / "modular-coupler.yaml", b / "out").exit_code, 0);
    EXPECT_EQ(tree(a / "out"), tree(b / "out"));
}

TEST(EsiDocCli, LanguageAndDeviceOptionsApply) {
    TempDir dir;
    const auto r = esi_doc(samples_dir() / "digital-io-8.yaml", dir / "out", {"--lang", "de", "--device", "0x1002"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = tree(dir / "out");
    ASSERT_EQ(files.size(), 2u);
    EXPECT_NE(files.at("EX-DIO-8B-rev00010000.html").find("EX-DIO-8B 8 Eingänge, 8 Ausgänge (Bits)"), std::string::npos);
}

TEST(EsiDocCli, UsageErrorsExitTwoAndWriteNothing) {
    TempDir dir;
    const auto out = dir / "out";
    const auto check = [&](const std::vector<std::string>& extra, const std::string& message) {
        const auto r = esi_doc(sample_esi(), out, extra);
        EXPECT_EQ(r.exit_code, 2) << message;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    };
    check({"--lang", "xx"}, "esi-doc: --lang: 'xx' is neither a language code");
    check({"--device", "nonsense"}, "esi-doc: --device:");
    check({"--device", "0x7777"}, "--device matches no device of the file [doc-no-device]");
    check({"--templates", (dir / "nope").string()}, "is not a directory");
    const auto missing = esi_doc(dir / "missing.xml", out);
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(EsiDocCli, ASourceWithErrorsExitsTwoWithLocatedMessages) {
    TempDir dir;
    write_text(dir / "bad.yaml", "vendor: { id: 0x0E4A, name: X }\ndevices:\n  - type: A\n    product_code: [1]\n");
    const auto r = esi_doc(dir / "bad.yaml", dir / "out");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.yaml:4:"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(EsiDocCli, ABrokenTemplateExitsOneAndLeavesTheOutputAsItWas) {
    TempDir dir;
    write_text(dir / "templates" / "device.html.mustache", "{{#device}}\n{{/pdos}}\n");
    write_text(dir / "out" / "index.html", "previous");
    const auto r = esi_doc(sample_esi(), dir / "out", {"--templates", (dir / "templates").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("device.html.mustache:1:1: error: Unclosed section \"device\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[doc-template-error]"), std::string::npos) << r.err;
    const auto files = tree(dir / "out");
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files.at("index.html"), "previous");
}

TEST(EsiDocCli, VersionAndHelp) {
    const auto version = run({tool("esi-doc").string(), "--version"});
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_EQ(version.out.rfind("esi-doc (libesi) ", 0), 0u) << version.out;
    const auto help = run({tool("esi-doc").string(), "--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("--templates"), std::string::npos);
    EXPECT_EQ(run({tool("esi-doc").string()}).exit_code, 2);
}

}  // namespace
