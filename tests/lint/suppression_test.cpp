#include <gtest/gtest.h>

#include "esi/lint/suppression.hpp"

namespace {
esi::Diagnostic at(std::uint32_t line, std::string rule) {
    esi::Diagnostic d;
    d.rule = std::move(rule);
    d.pos = {line, 1};
    return d;
}
}  // namespace

TEST(Suppression, DisableUntilEnable) {
    esi::SourceText text("f.xml", "<a>\n<!-- esi-lint: disable=xml-hex-prefix -->\n<b/>\n<!-- esi-lint: enable=xml-hex-prefix -->\n<c/>\n</a>\n");
    esi::Diagnostics diags;
    const auto s = esi::find_suppressions(text, diags);
    EXPECT_TRUE(diags.empty());
    EXPECT_FALSE(s.suppresses(at(1, "xml-hex-prefix")));
    EXPECT_TRUE(s.suppresses(at(3, "xml-hex-prefix")));
    EXPECT_FALSE(s.suppresses(at(5, "xml-hex-prefix")));
    EXPECT_FALSE(s.suppresses(at(3, "xml-number-format")));
}

TEST(Suppression, NextLineAndAll) {
    esi::SourceText text("f.xml", "<a>\n<!-- esi-lint: disable-next-line=all -->\n<b/>\n<c/>\n</a>\n");
    esi::Diagnostics diags;
    const auto s = esi::find_suppressions(text, diags);
    EXPECT_TRUE(s.suppresses(at(3, "xml-number-format")));
    EXPECT_FALSE(s.suppresses(at(4, "xml-number-format")));
}

TEST(Suppression, SyntaxErrorsCannotBeSuppressed) {
    esi::SourceText text("f.xml", "<!-- esi-lint: disable=all -->\n<a>\n");
    esi::Diagnostics diags;
    const auto s = esi::find_suppressions(text, diags);
    EXPECT_FALSE(s.suppresses(at(2, "xml-syntax")));
}

TEST(Suppression, MalformedDirectiveAndUnknownRuleAreReported) {
    esi::SourceText text("f.xml", "<a>\n<!-- esi-lint: disabel=x -->\n<!-- esi-lint: disable=no-such-rule -->\n</a>\n");
    esi::Diagnostics diags;
    (void)esi::find_suppressions(text, diags);
    ASSERT_EQ(diags.size(), 2u);
    EXPECT_EQ(diags.items()[0].rule, "lint-directive");
    EXPECT_EQ(diags.items()[0].pos.line, 2u);
    EXPECT_EQ(diags.items()[1].pos.line, 3u);
}

TEST(Suppression, MarkerOutsideCommentsIsIgnored) {
    esi::SourceText text("f.xml", "<a>esi-lint: disable=all</a>\n");
    esi::Diagnostics diags;
    const auto s = esi::find_suppressions(text, diags);
    EXPECT_TRUE(s.regions.empty());
}
