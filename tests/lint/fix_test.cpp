// Safe fixes (issue 22): lint → fix → lint. Each fix makes its finding go away and nothing new
// appear; only the fixed bytes change (encoding, line endings, comments stay); a file valid
// against the ETG schema stays valid.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "esi/lint/fix.hpp"
#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

using esi::apply_fixes;
using esi::EffectiveConfig;
using esi::FixedText;

std::size_t count_rule(std::string_view text, const std::string& rule) {
    const esi::FileReport r = esi::lint_bytes(text, "f.xml", EffectiveConfig{});
    std::size_t n = 0;
    for (const auto& d : r.diagnostics) n += d.rule == rule;
    return n;
}

std::string info(std::string vendor_id, std::string line_end = "\n") {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>" + line_end + "<!-- kept as it is -->" + line_end + "<EtherCATInfo>" + line_end +
           "  <Vendor>" + line_end + "    <Id>" + vendor_id + "</Id>" + line_end + "    <Name>Example</Name>" + line_end + "  </Vendor>" +
           line_end + "  <Descriptions><Groups/><Devices/></Descriptions>" + line_end + "</EtherCATInfo>" + line_end;
}

TEST(SafeFix, HexPrefixBecomesHashX) {
    const std::string before = info("0xF3F");
    ASSERT_EQ(count_rule(before, "xml-hex-prefix"), 1u);
    const FixedText fixed = apply_fixes(before, "f.xml", EffectiveConfig{});
    EXPECT_TRUE(fixed.refused.empty()) << fixed.refused;
    EXPECT_EQ(fixed.applied, 1u);
    EXPECT_EQ(fixed.bytes, info("#xF3F"));
    EXPECT_EQ(count_rule(fixed.bytes, "xml-hex-prefix"), 0u);
}

TEST(SafeFix, LineEndingsAndCommentsStayByteIdentical) {
    const FixedText fixed = apply_fixes(info("  0X10  ", "\r\n"), "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.bytes, info("  #x10  ", "\r\n"));
}

TEST(SafeFix, DoublePrefixLosesTheSecond) {
    const std::string before = info("#x0x0F3F");
    ASSERT_EQ(count_rule(before, "xml-number-format"), 1u);
    const FixedText fixed = apply_fixes(before, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.bytes, info("#x0F3F"));
    EXPECT_EQ(count_rule(fixed.bytes, "xml-number-format"), 0u);
}

TEST(SafeFix, WhatIsNotCertainIsLeftAlone) {
    for (const char* value : {"#x0xZZ", "12h", "0x"}) {
        const FixedText fixed = apply_fixes(info(value), "f.xml", EffectiveConfig{});
        EXPECT_EQ(fixed.applied, 0u) << value;
        EXPECT_EQ(fixed.bytes, info(value)) << value;
    }
    // After a character reference the value has moved in the parse buffer: no fix rather than a wrong one.
    const FixedText entity = apply_fixes(info("&#32;0x10"), "f.xml", EffectiveConfig{});
    EXPECT_EQ(entity.bytes, info("&#32;0x10"));
}

TEST(SafeFix, AttributesAreFixedInPlace) {
    std::string text = esi::test::read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml");
    const auto at = text.find("StartAddress=\"#x");
    ASSERT_NE(at, std::string::npos);
    std::string broken = text;
    broken.replace(at + 14, 2, "0x");
    const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.applied, 1u) << fixed.refused;
    EXPECT_EQ(fixed.bytes, text);
}

TEST(SafeFix, ATwinCatTypeAliasBecomesTheStandardName) {
    const std::string text = esi::test::read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml");
    const std::string good = "<Name>Digital outputs</Name>\n            <DataType>USINT</DataType>";
    const auto at = text.find(good);
    ASSERT_NE(at, std::string::npos);
    std::string alias = text;
    alias.replace(at + good.find("USINT"), 5, "UINT8");
    ASSERT_EQ(count_rule(alias, "pdo-entry-type-spelling"), 1u);
    const FixedText fixed = apply_fixes(alias, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.applied, 1u) << fixed.refused;
    EXPECT_EQ(fixed.bytes, text);

    // Text the fix cannot be sure of (the alias after a comment) is left alone.
    std::string partial = text;
    partial.replace(at + good.find("USINT"), 5, "<!-- c -->UINT8");
    EXPECT_EQ(apply_fixes(partial, "f.xml", EffectiveConfig{}).bytes, partial);
}

TEST(SafeFix, SingleByteEncodingsMapOffsetsToBytes) {
    // ISO-8859-1: 'ä' is one byte in the file and two in the decoded text, before the fix.
    const std::string before = "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n<EtherCATInfo>\n  <Vendor>\n    <Name>K\xE4se</Name>\n"
                               "    <Id>0x10</Id>\n  </Vendor>\n  <Descriptions><Groups/><Devices/></Descriptions>\n</EtherCATInfo>\n";
    std::string expected = before;
    expected.replace(expected.find("0x10"), 2, "#x");
    const FixedText fixed = apply_fixes(before, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.applied, 1u) << fixed.refused;
    EXPECT_EQ(fixed.bytes, expected);
}

TEST(SafeFix, AByteOrderMarkStays) {
    const std::string before = "\xEF\xBB\xBF" + info("0x10");
    const FixedText fixed = apply_fixes(before, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.bytes, "\xEF\xBB\xBF" + info("#x10"));
}

TEST(SafeFix, Utf16IsRefusedNotGarbled) {
    std::string utf8 = info("0x10");
    utf8.replace(utf8.find("UTF-8"), 5, "UTF-16");
    std::string utf16 = "\xFF\xFE";
    for (char c : utf8) {
        utf16.push_back(c);
        utf16.push_back('\0');
    }
    const FixedText fixed = apply_fixes(utf16, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.applied, 0u);
    EXPECT_FALSE(fixed.refused.empty());
    EXPECT_EQ(fixed.bytes, utf16);
}

TEST(SafeFix, ASwitchedOffRuleIsNotFixed) {
    EffectiveConfig config;
    config.rules["xml-hex-prefix"] = esi::RuleSetting::off;
    const FixedText fixed = apply_fixes(info("0x10"), "f.xml", config);
    EXPECT_EQ(fixed.applied, 0u);
    EXPECT_EQ(fixed.bytes, info("0x10"));
}

TEST(SafeFix, UnifiedDiffShowsTheChangedLineWithContext) {
    const std::string before = info("0xF3F");
    const FixedText fixed = apply_fixes(before, "f.xml", EffectiveConfig{});
    const std::string diff = esi::unified_diff(fixed.original, fixed.edits, "f.xml");
    EXPECT_EQ(diff,
              "--- a/f.xml\n+++ b/f.xml\n@@ -2,7 +2,7 @@\n <!-- kept as it is -->\n <EtherCATInfo>\n   <Vendor>\n"
              "-    <Id>0xF3F</Id>\n+    <Id>#xF3F</Id>\n     <Name>Example</Name>\n   </Vendor>\n"
              "   <Descriptions><Groups/><Devices/></Descriptions>\n");
}

TEST(SafeFix, UnifiedDiffAppliesWithPatch) {
    // The diff is what `patch` expects: applied to the original it gives the fixed file.
    if (std::system("patch --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "patch is not installed";
    std::string text = esi::test::read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml");
    std::string broken = text;
    for (std::size_t at = 0, n = 0; n < 5 && (at = broken.find(">#x", at)) != std::string::npos; ++n, at += 300)
        broken.replace(at + 1, 2, "0x");
    const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
    ASSERT_EQ(fixed.applied, 5u) << fixed.refused;
    esi::test::TempDir dir;
    esi::test::write_text(dir / "f.xml", broken);
    esi::test::write_text(dir / "fix.diff", esi::unified_diff(fixed.original, fixed.edits, "f.xml"));
    const auto r = esi::test::run({"patch", "-p1", "-s", "-i", "fix.diff"}, {}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(esi::test::read_text(dir / "f.xml"), text);
}

TEST(SafeFix, AFileValidAgainstTheSchemaStaysValid) {
    ESI_REQUIRE_CORPUS();
    const auto xsd = esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022" / "EtherCATInfo.xsd";
    if (std::system("xmllint --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "xmllint is not installed";
    const std::string text = esi::test::read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml");
    esi::test::TempDir dir;
    auto valid = [&](const std::string& content) {
        esi::test::write_text(dir / "f.xml", content);
        return esi::test::run({"xmllint", "--noout", "--nonet", "--schema", xsd.string(), (dir / "f.xml").string()}).exit_code == 0;
    };
    ASSERT_TRUE(valid(text)) << "the sample is schema-valid to begin with";
    std::string broken = text;
    for (std::size_t at = 0; (at = broken.find(">#x", at)) != std::string::npos; at += 3) broken.replace(at + 1, 2, "0x");
    EXPECT_FALSE(valid(broken));
    const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
    EXPECT_GT(fixed.applied, 10u) << fixed.refused;
    EXPECT_TRUE(valid(fixed.bytes));
    EXPECT_EQ(fixed.bytes, text);
}

}  // namespace
