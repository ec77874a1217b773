// Suppression edits land where a comment may stand, and 8-bit files keep their fixes.

#include <gtest/gtest.h>

#include <algorithm>

#include "esi/lint/lint.hpp"
#include "esi/lsp/code_actions.hpp"
#include "esi/lsp/lint_document.hpp"
#include "support/test_support.hpp"

namespace {

std::string apply(std::string text, const std::vector<esi::TextEdit>& edits) {
    for (auto it = edits.rbegin(); it != edits.rend(); ++it) text.replace(it->offset, it->length, it->replacement);
    return text;
}

std::size_t count_rule(const esi::FileReport& report, const std::string& rule) {
    std::size_t n = 0;
    for (const auto& d : report.diagnostics) n += d.rule == rule;
    return n;
}

std::string sample() { return esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml"); }

TEST(LspSuppression, InsideAMultiLineStartTagTheTagIsWrapped) {
    // The finding's attribute on the second line of a start tag: a comment may not stand there.
    std::string text = sample();
    const std::size_t at = text.find("ProductCode=\"#x");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, std::string_view("ProductCode=\"#x").size(), "\n            ProductCode=\"0x");
    const esi::FileReport before = esi::lint_bytes(text, "d.xml", esi::EffectiveConfig{});
    ASSERT_EQ(count_rule(before, "xml-hex-prefix"), 1u);
    // The attribute's own line (where an editor's cursor is), inside the start tag.
    const auto line = static_cast<std::uint32_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at) + 1, '\n') + 1);
    const std::vector<esi::TextEdit> edits = esi::lsp::suppression_edits(text, line, "xml-hex-prefix");
    ASSERT_EQ(edits.size(), 2u);
    const esi::FileReport after = esi::lint_bytes(apply(text, edits), "d.xml", esi::EffectiveConfig{});
    EXPECT_EQ(count_rule(after, "xml-hex-prefix"), 0u);
    EXPECT_EQ(count_rule(after, "xml-syntax"), 0u);
    EXPECT_EQ(after.diagnostics.size(), before.diagnostics.size() - 1);
}

TEST(LspLintDocument, Latin1FileKeepsItsFixOffsets) {
    // The editor sends UTF-8; the file declares ISO-8859-1 and has an 'ü' before the finding.
    std::string text = sample();
    text.replace(text.find("encoding=\"UTF-8\""), std::string_view("encoding=\"UTF-8\"").size(), "encoding=\"ISO-8859-1\"");
    text.insert(text.find("?>") + 2, "\n<!-- M\xC3\xBCller -->");
    text.replace(text.find("<Id>#x"), 6, "<Id>0x");
    const esi::lsp::DocumentLint lint = esi::lsp::lint_document(text, "");
    EXPECT_TRUE(lint.fixes_apply);
    ASSERT_EQ(count_rule(lint.report, "xml-hex-prefix"), 1u) << (lint.report.diagnostics.empty() ? "" : lint.report.diagnostics.items()[0].message);
    for (const auto& d : lint.report.diagnostics) {
        if (!d.fix) continue;
        const esi::TextEdit& edit = d.fix->edits.at(0);
        EXPECT_EQ(text.substr(edit.offset, edit.length), "0x");
    }
}

}  // namespace
