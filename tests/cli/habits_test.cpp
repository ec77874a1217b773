// What a new user types and expects from other tools (issue 14, item 6): `-` for standard input
// in esi-diff, did-you-mean for a misspelt rule id, --color=WHEN with NO_COLOR, and a clear
// message for a misspelt subcommand.

#include <gtest/gtest.h>

#include <cstdlib>

#include "support/test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string sample() { return (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string(); }
std::string findings() { return (esi::test::source_dir() / "tests" / "cli" / "data" / "findings.xml").string(); }
bool has_escape(const std::string& text) { return text.find("\x1b[") != std::string::npos; }

// `command` run under a pseudo-terminal (util-linux script), so that isatty(stdout) is true.
std::string run_on_terminal(const std::string& command) {
    TempDir dir;
    const auto r = run({"script", "-qec", command + " > /dev/tty", "/dev/null"}, {}, dir.path());
    return r.out;
}

bool have_script() { return std::system("script -qec true /dev/null > /dev/null 2>&1") == 0; }

}  // namespace

TEST(EsiDiffStdin, DashIsStandardInput) {
    const std::string bytes = read_text(sample());
    const auto same = run({tool("esi-diff"), "-", sample()}, bytes);
    EXPECT_EQ(same.exit_code, 0) << same.out << same.err;

    TempDir dir;
    std::string changed = bytes;
    const auto at = changed.find("<Vendor>");
    ASSERT_NE(at, std::string::npos);
    changed.insert(at, "<!-- moved -->");
    write_text(dir / "new.xml", changed);
    const auto r = run({tool("esi-diff"), "--fail-on", "any", "-", (dir / "new.xml").string()}, bytes);
    EXPECT_EQ(r.exit_code, 0) << "a comment is no change: " << r.out << r.err;
}

TEST(EsiDiffStdin, NamesStandardInputInItsFindings) {
    TempDir dir;
    std::string changed = read_text(sample());
    const auto at = changed.find("<Name LcId=\"1033\">");
    ASSERT_NE(at, std::string::npos);
    changed.replace(at, 18, "<Name LcId=\"1033\">Renamed ");
    write_text(dir / "new.xml", changed);
    const auto r = run({tool("esi-diff"), "--fail-on", "any", "-", (dir / "new.xml").string()}, read_text(sample()));
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("<stdin>"), std::string::npos) << r.out;
}

TEST(EsiDiffStdin, UnreadableStandardInputIsExitTwo) {
    const auto broken = run({tool("esi-diff"), "-", sample()}, "<EtherCATInfo><Vendor>");
    EXPECT_EQ(broken.exit_code, 2);
    EXPECT_NE((broken.out + broken.err).find("<stdin>:1:"), std::string::npos) << broken.out << broken.err;
    const auto both = run({tool("esi-diff"), "-", "-"}, read_text(sample()));
    EXPECT_EQ(both.exit_code, 2);
    EXPECT_NE(both.err.find("only one of OLD and NEW"), std::string::npos) << both.err;
}

TEST(EsiLintExplain, UnknownRuleSuggestsTheNearest) {
    const auto r = run({tool("esi-lint"), "--explain", "xml-hex-prefx"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown rule 'xml-hex-prefx'; did you mean 'xml-hex-prefix'?"), std::string::npos) << r.err;
    const auto far = run({tool("esi-lint"), "--explain", "completely-unrelated-words"});
    EXPECT_EQ(far.exit_code, 2);
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST(EsiLintColor, WhenIsAutoAlwaysOrNever) {
    EXPECT_FALSE(has_escape(run({tool("esi-lint"), findings()}).out)) << "auto: a pipe is not coloured";
    EXPECT_TRUE(has_escape(run({tool("esi-lint"), "--color=always", findings()}).out));
    EXPECT_TRUE(has_escape(run({tool("esi-lint"), "--color", findings()}).out)) << "--color alone means always";
    EXPECT_FALSE(has_escape(run({tool("esi-lint"), "--color=never", findings()}).out));
    EXPECT_EQ(run({tool("esi-lint"), "--color=sometimes", findings()}).exit_code, 2);
    // An explicit --color=always wins over NO_COLOR (https://no-color.org).
    EXPECT_TRUE(has_escape(run({"env", "NO_COLOR=1", tool("esi-lint"), "--color=always", findings()}).out));
    const auto help = run({tool("esi-lint"), "--help"});
    EXPECT_NE(help.out.find("NO_COLOR"), std::string::npos) << help.out;
}

TEST(EsiLintColor, AutoColoursATerminalUnlessNoColorIsSet) {
    if (!have_script()) GTEST_SKIP() << "script (util-linux) not available: no pseudo-terminal to test --color=auto on";
    const std::string lint = tool("esi-lint").string() + " " + findings();
    EXPECT_TRUE(has_escape(run_on_terminal(lint)));
    EXPECT_FALSE(has_escape(run_on_terminal("NO_COLOR=1 " + lint)));
    EXPECT_TRUE(has_escape(run_on_terminal("NO_COLOR= " + lint))) << "an empty NO_COLOR does not count";
}

TEST(Subcommands, AMisspeltSubcommandIsNamedWithTheValidOnes) {
    const auto r = run({tool("esi-sii"), "biuld", "x.xml"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("esi-sii: unknown subcommand 'biuld'; did you mean 'build'? (subcommands: build, dump or check"),
              std::string::npos)
        << r.err;
    const auto none = run({tool("esi-sii")});
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_NE(none.err.find("esi-sii: a subcommand is required: build, dump or check"), std::string::npos) << none.err;
    // A valid subcommand with a missing argument keeps CLI11's own message.
    const auto missing = run({tool("esi-sii"), "build"});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("input is required"), std::string::npos) << missing.err;
}
