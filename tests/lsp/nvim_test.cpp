// Neovim's built-in LSP client, headless (tests/lsp/nvim_client.lua), against esi-lsp: the
// diagnostics it shows are esi-lint's for the file (rule ids and lines), a hover shows the object
// a PDO entry maps, go-to-definition moves the cursor to that object, and a quick fix applied by
// the editor changes the buffer as esi-lint --fix changes the file. Skips without nvim.

#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

bool have_nvim() { return esi::test::run({"sh", "-c", "command -v nvim"}).exit_code == 0; }

std::set<std::string> lines_of(const std::string& text) {
    std::set<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.insert(line);
    return out;
}

std::set<std::string> esi_lint_findings(const std::filesystem::path& file) {
    std::set<std::string> out;
    const esi::LintReport report = esi::lint_paths({file}, {});
    for (const auto& d : report.files.at(0).diagnostics) out.insert(d.rule + " " + std::to_string(d.pos.line));
    return out;
}

struct NvimRun {
    std::string error;
    std::set<std::string> diagnostics;
    std::string buffer;
    std::set<std::string> after;
    std::string hover;       // with `at`: the hover's markdown
    std::string definition;  // with `at`: "ROW COL" of the cursor after the jump
};

// `at`: "LINE,CHARACTER" (0-based) to hover and jump from, or empty.
NvimRun run_nvim(const std::filesystem::path& file, const esi::test::TempDir& out, const std::string& at = "") {
    const std::string script = (esi::test::source_dir() / "tests/lsp/nvim_client.lua").string();
    const esi::test::RunResult result = esi::test::run(
        {"env", "ESI_NVIM_AT=" + at, "ESI_NVIM_OUT=" + out.path().string(), "ESI_NVIM_FILE=" + file.string(), "ESI_LSP=" + esi::test::tool("esi-lsp").string(),
         // Neovim's LSP log and state go to the test's directory, not to a home that may be read-only.
         "XDG_CACHE_HOME=" + out.path().string(), "XDG_STATE_HOME=" + out.path().string(), "XDG_DATA_HOME=" + out.path().string(),
         "timeout", "90", "nvim", "--headless", "--clean", "-n", "-i", "NONE", "-c", "luafile " + script});
    NvimRun run;
    if (std::filesystem::exists(out / "error.txt")) run.error = esi::test::read_text(out / "error.txt");
    else if (!std::filesystem::exists(out / "done.txt"))
        run.error = "nvim did not finish (exit " + std::to_string(result.exit_code) + "): " + result.err + result.out;
    if (std::filesystem::exists(out / "diagnostics.txt")) run.diagnostics = lines_of(esi::test::read_text(out / "diagnostics.txt"));
    if (std::filesystem::exists(out / "buffer.txt")) run.buffer = esi::test::read_text(out / "buffer.txt");
    if (std::filesystem::exists(out / "after.txt")) run.after = lines_of(esi::test::read_text(out / "after.txt"));
    if (std::filesystem::exists(out / "hover.txt")) run.hover = esi::test::read_text(out / "hover.txt");
    if (std::filesystem::exists(out / "definition.txt")) run.definition = esi::test::read_text(out / "definition.txt");
    return run;
}

TEST(LspNeovim, DiagnosticsAreEsiLintsAndTheQuickFixApplies) {
    if (!have_nvim()) GTEST_SKIP() << "nvim not installed (Debian package neovim): Neovim test skipped";
    esi::test::TempDir dir;
    std::string text = esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml");
    const std::size_t at = text.find("<Id>#x");
    ASSERT_NE(at, std::string::npos);
    std::string broken = text;
    broken.replace(at, 6, "<Id>0x");
    const std::filesystem::path file = dir / "device.xml";
    esi::test::write_text(file, broken);
    const std::set<std::string> expected = esi_lint_findings(file);
    ASSERT_FALSE(expected.empty());

    esi::test::TempDir out;
    // Line 180 (0-based 179) is the RxPdo entry's "            <Index>#x7000</Index>"; the
    // object #x7000 is defined on line 159, its index at byte column 23.
    const NvimRun run = run_nvim(file, out, "179,21");
    ASSERT_TRUE(run.error.empty()) << run.error;
    EXPECT_EQ(run.diagnostics, expected);
    EXPECT_EQ(run.hover, "**#x7000 Digital outputs**\n\n- type: `USINT`\n- size: 8 bits\n- access: rw\n- PDO mapping: R\n- default: `0`\n\n");
    EXPECT_EQ(run.definition, "159 23\n");
    // The buffer after the quick fix is the file as it was before it was broken.
    EXPECT_EQ(run.buffer, text);
    EXPECT_TRUE(run.after.empty()) << *run.after.begin();
}

TEST(LspNeovim, CorpusFileShowsEsiLintsFindings) {
    if (!have_nvim()) GTEST_SKIP() << "nvim not installed (Debian package neovim): Neovim test skipped";
    ESI_REQUIRE_CORPUS();
    // UTF-8 and ISO-8859-1 catalogues, as Neovim reads and sends them.
    for (const char* name : {"Beckhoff__EL66xx__dls-ethercat.xml", "Beckhoff__BKxxxxModules__dls-ethercat__2013-03.xml"}) {
        esi::test::TempDir dir;
        const std::filesystem::path file = dir / name;
        std::filesystem::copy_file(esi::test::corpus_esi_dir() / name, file);
        esi::test::TempDir out;
        const NvimRun run = run_nvim(file, out);
        ASSERT_TRUE(run.error.empty()) << name << ": " << run.error;
        const std::set<std::string> expected = esi_lint_findings(file);
        EXPECT_FALSE(expected.empty()) << name << ": chosen for its findings";
        EXPECT_EQ(run.diagnostics, expected) << name;
    }
}

}  // namespace
