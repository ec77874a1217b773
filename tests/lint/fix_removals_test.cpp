// Safe fixes that remove or declare (issue 22): obsolete attributes no tool reads, byte-identical
// copies of an element, and the xmlns:xsi declaration of a used xsi: prefix. Each is checked by
// lint → fix → lint: the finding is gone, nothing new appears and every other byte stays,
// whatever the file's encoding and line endings.

#include <gtest/gtest.h>

#include <cstdlib>

#include "esi/lint/fix.hpp"
#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

using esi::apply_fixes;
using esi::EffectiveConfig;
using esi::FixedText;

std::string sample() { return esi::test::read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml"); }

std::size_t count_rule(std::string_view text, const std::string& rule) {
    const esi::FileReport r = esi::lint_bytes(text, "f.xml", EffectiveConfig{});
    std::size_t n = 0;
    for (const auto& d : r.diagnostics) n += d.rule == rule;
    return n;
}

void replace_once(std::string& text, std::string_view what, std::string_view with) {
    const auto at = text.find(what);
    ASSERT_NE(at, std::string::npos) << what;
    text.replace(at, what.size(), with);
}

// The sample with CRLF line endings.
std::string crlf(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n') out += '\r';
        out += c;
    }
    return out;
}

// The sample (UTF-8) as ISO-8859-1, declared so: its umlauts become one byte each.
std::string latin1(const std::string& utf8) {
    std::string out;
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const auto c = static_cast<unsigned char>(utf8[i]);
        if (c == 0xC3 && i + 1 < utf8.size()) out += static_cast<char>(0x40 + static_cast<unsigned char>(utf8[++i]));
        else out += utf8[i];
    }
    replace_once(out, "encoding=\"UTF-8\"", "encoding=\"ISO-8859-1\"");
    return out;
}

// lint → fix → lint: `broken` has `count` findings of `rule`, the fix removes them all and gives `expected`.
void expect_fixed(const std::string& broken, const std::string& rule, std::size_t count, const std::string& expected) {
    SCOPED_TRACE(rule + (broken.find('\r') != std::string::npos ? " (CRLF)" : "") +
                 (broken.find("ISO-8859-1") != std::string::npos ? " (ISO-8859-1)" : ""));
    ASSERT_EQ(count_rule(broken, rule), count);
    const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
    EXPECT_TRUE(fixed.refused.empty()) << fixed.refused;
    EXPECT_EQ(fixed.applied, count);
    EXPECT_EQ(fixed.bytes, expected);
    EXPECT_EQ(count_rule(fixed.bytes, rule), 0u);
}

// The text from the line holding `start` to the end of the line holding the matching `end` after it.
std::string lines_of_element(const std::string& text, std::string_view start, std::string_view end) {
    const auto at = text.find(start);
    const auto from = text.rfind('\n', at) + 1;
    const auto to = text.find('\n', text.find(end, at)) + 1;
    return text.substr(from, to - from);
}

// The text with the lines of the element repeated right after it.
std::string with_copy(const std::string& text, std::string_view start, std::string_view end) {
    const std::string lines = lines_of_element(text, start, end);
    std::string out = text;
    out.insert(text.find(lines) + lines.size(), lines);
    return out;
}

TEST(SafeFixRemovals, ObsoleteAttributesAreRemovedWithTheirBlanks) {
    for (const std::string& good : {sample(), crlf(sample()), latin1(sample())}) {
        std::string broken = good;
        replace_once(broken, "<Vendor>", "<Vendor UniqueName=\"Beispiel Käse\">");
        replace_once(broken, "RevisionNo=\"#x00010000\"", "RevisionNo=\"#x00010000\" TcCfgModeSafeOp=\"true\"");
        replace_once(broken, "DefaultSize=\"128\"", "DefaultSize=\"128\"  OneByteMode=\"false\"");
        if (good.find("ISO-8859-1") != std::string::npos) {
            // Latin-1: the value the fix removes holds a one-byte umlaut.
            broken = broken.substr(0, broken.find("K\xC3\xA4se")) + "K\xE4se" + broken.substr(broken.find("K\xC3\xA4se") + 5);
        }
        const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
        EXPECT_TRUE(fixed.refused.empty()) << fixed.refused;
        EXPECT_EQ(fixed.applied, 3u);
        EXPECT_EQ(fixed.bytes, good);
    }
}

TEST(SafeFixRemovals, AnAttributeOnALineOfItsOwnTakesTheLine) {
    const std::string good = sample();
    std::string broken = good;
    replace_once(broken, "<Sm StartAddress=\"#x1000\"", "<Sm\n          FixedAssignment=\"true\"\n          StartAddress=\"#x1000\"");
    std::string expected = good;
    replace_once(expected, "<Sm StartAddress=\"#x1000\"", "<Sm\n          StartAddress=\"#x1000\"");
    expect_fixed(broken, "deprecated-obsolete", 1, expected);
}

TEST(SafeFixRemovals, EveryRemovableObsoleteAttributeGoes) {
    const std::string good = sample();
    std::string broken = good;
    replace_once(broken, "RevisionNo=\"#x00010000\">", "RevisionNo=\"#x00010000\" TcSmClass=\"x\" DownloadModuleList=\"y\">");
    replace_once(broken, "Enable=\"1\">MBoxOut", "Enable=\"1\" Watchdog=\"false\" FixedAssignment=\"true\">MBoxOut");
    const std::string coe = "CompleteAccess=\"false\"/>";
    std::string with_cmd = good;
    replace_once(with_cmd, coe, "CompleteAccess=\"false\"><InitCmd><Transition>PS</Transition><Index>#x1C12</Index>"
                                "<SubIndex>0</SubIndex><Data>00</Data></InitCmd></CoE>");
    replace_once(broken, coe, "CompleteAccess=\"false\"><InitCmd Fixed=\"true\"><Transition>PS</Transition><Index>#x1C12</Index>"
                              "<SubIndex>0</SubIndex><Data>00</Data></InitCmd></CoE>");
    expect_fixed(broken, "deprecated-obsolete", 5, with_cmd);
}

TEST(SafeFixRemovals, WhatCarriesMeaningIsNotRemoved) {
    // Watchdog="true" asks for ControlByte bit 6 (a change of another value), Profile@Channel for
    // ChannelCount: the finding stays without a fix.
    std::string broken = sample();
    replace_once(broken, "DefaultSize=\"128\"", "DefaultSize=\"128\" Watchdog=\"true\"");
    const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.applied, 0u);
    EXPECT_EQ(fixed.bytes, broken);
    EXPECT_EQ(count_rule(broken, "deprecated-obsolete"), 1u);
}

TEST(SafeFixRemovals, AByteIdenticalCopyIsRemovedWithItsLines) {
    for (const std::string& good : {sample(), crlf(sample()), latin1(sample())}) {
        expect_fixed(with_copy(good, "<RxPdo Fixed=", "</RxPdo>"), "pdo-duplicate-index", 1, good);
        expect_fixed(with_copy(good, "<OpMode>", "</OpMode>"), "dc-opmode-duplicate", 1, good);
        const std::string newline = good.find('\r') != std::string::npos ? "\r\n" : "\n";
        expect_fixed(with_copy(good, "<DataType>" + newline + "                <Name>DT1018", "</DataType>"), "od-duplicate-datatype", 1, good);
        // The Identity object's names hold no umlauts, Device type's neither; the copy is all ASCII
        // or not: either way its bytes go.
        expect_fixed(with_copy(good, "<Object>", "</Object>"), "od-duplicate-object", 1, good);
    }
}

TEST(SafeFixRemovals, ACopyThatDiffersInOneByteStays) {
    const std::string good = sample();
    const std::string lines = lines_of_element(good, "<OpMode>", "</OpMode>");
    std::string changed = lines;
    replace_once(changed, "<OpMode>", "<OpMode> ");
    std::string broken = good;
    broken.insert(good.find(lines) + lines.size(), changed);
    ASSERT_EQ(count_rule(broken, "dc-opmode-duplicate"), 1u);
    const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.applied, 0u);
    EXPECT_EQ(fixed.bytes, broken);
}

TEST(SafeFixRemovals, ACopyOnTheSameLineGoesWithoutTheLine) {
    const std::string good = sample();
    const std::string line = lines_of_element(good, "<DataType><Name>UINT</Name>", "</DataType>");
    const std::string element = line.substr(line.find('<'), line.rfind('>') + 1 - line.find('<'));
    std::string broken = good;
    replace_once(broken, element, element + " " + element);
    std::string expected = good;
    replace_once(expected, element, element + " ");
    expect_fixed(broken, "od-duplicate-datatype", 1, expected);
}

TEST(SafeFixRemovals, AMissingXsiDeclarationIsAddedOnTheRoot) {
    const std::string declaration = " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"";
    for (const std::string& good : {sample(), crlf(sample()), latin1(sample())}) {
        std::string broken = good;
        replace_once(broken, declaration, "");
        // Declared right after the root's name: every other byte stays.
        std::string expected = broken;
        replace_once(expected, "<EtherCATInfo", "<EtherCATInfo" + declaration);
        expect_fixed(broken, "xml-undeclared-prefix", 1, expected);
    }
}

TEST(SafeFixRemovals, AnUndeclaredPrefixIsReportedOnceAndOnlyXsiIsFixed) {
    std::string broken = sample();
    replace_once(broken, "<Vendor>", "<Vendor abc:note=\"1\" abc:other=\"2\">");
    const esi::FileReport r = esi::lint_bytes(broken, "f.xml", EffectiveConfig{});
    std::size_t n = 0;
    for (const auto& d : r.diagnostics)
        if (d.rule == "xml-undeclared-prefix") {
            ++n;
            EXPECT_EQ(d.severity, esi::Severity::error);
            EXPECT_EQ(d.pos.line, 5u);
            EXPECT_NE(d.message.find("'abc'"), std::string::npos) << d.message;
            EXPECT_FALSE(d.fix.has_value());
        }
    EXPECT_EQ(n, 1u);
    // Declared on an enclosing element: fine.
    replace_once(broken, "<Vendor ", "<Vendor xmlns:abc=\"urn:example\" ");
    EXPECT_EQ(count_rule(broken, "xml-undeclared-prefix"), 0u);
}

TEST(SafeFixRemovals, APrefixDeclaredOnlyElsewhereIsUndeclaredHere) {
    std::string text = sample();
    // Text that looks like a prefix (a colon between words) is no name.
    replace_once(text, "<Name LcId=\"1033\">Example Automation GmbH</Name>",
                 "<Name LcId=\"1033\">Example Automation GmbH</Name><!-- note:kept --><URL>see: http://example.com x:y</URL>");
    EXPECT_EQ(count_rule(text, "xml-undeclared-prefix"), 0u);
    // Declared on the Vendor, used on Descriptions: out of the declaration's scope.
    replace_once(text, "<Vendor>", "<Vendor xmlns:abc=\"urn:example\" abc:note=\"1\">");
    EXPECT_EQ(count_rule(text, "xml-undeclared-prefix"), 0u);
    replace_once(text, "<Descriptions>", "<Descriptions abc:note=\"2\">");
    EXPECT_EQ(count_rule(text, "xml-undeclared-prefix"), 1u);
}

TEST(SafeFixRemovals, FixedFilesStaySchemaValid) {
    ESI_REQUIRE_CORPUS();
    const auto xsd = esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022" / "EtherCATInfo.xsd";
    if (std::system("xmllint --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "xmllint is not installed";
    esi::test::TempDir dir;
    auto valid = [&](const std::string& content) {
        esi::test::write_text(dir / "f.xml", content);
        return esi::test::run({"xmllint", "--noout", "--nonet", "--schema", xsd.string(), (dir / "f.xml").string()}).exit_code == 0;
    };
    const std::string good = sample();
    ASSERT_TRUE(valid(good));
    std::string broken = with_copy(good, "<OpMode>", "</OpMode>");
    replace_once(broken, "DefaultSize=\"128\"", "DefaultSize=\"128\" OneByteMode=\"false\"");
    const FixedText fixed = apply_fixes(broken, "f.xml", EffectiveConfig{});
    EXPECT_EQ(fixed.applied, 2u) << fixed.refused;
    EXPECT_TRUE(valid(fixed.bytes));
}

}  // namespace
