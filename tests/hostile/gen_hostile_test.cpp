// esi-gen and esi-diff on hostile ESI sources: a source with errors is exit code 2 and nothing is
// written; a DOCTYPE's entities are not expanded into generated code; esi-diff reports an
// unreadable side with its position and exit code 2.

#include <gtest/gtest.h>

#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::run_child;

struct BrokenSource {
    const char* name;
    std::string text;
};

std::vector<BrokenSource> broken_sources() {
    const std::string sample = esi::test::sample_esi();
    std::string nul = sample;
    nul[nul.find("Example Automation")] = '\0';
    std::string deep = "<?xml version=\"1.0\"?>\n<EtherCATInfo>";
    for (int i = 0; i < 100'000; ++i) deep += "<a>";
    for (int i = 0; i < 100'000; ++i) deep += "</a>";
    deep += "</EtherCATInfo>\n";
    return {
        {"nul", nul},
        {"deep", deep},
        {"bad-utf8", esi::test::replace_once(sample, "Example Automation", "Example \xC3\x28utomation")},
        {"truncated", sample.substr(0, sample.size() / 3)},
        {"empty", ""},
        {"hex-without-digits", esi::test::replace_once(sample, "ProductCode=\"#x00001001\"", "ProductCode=\"#x\"")},
        {"huge-number", esi::test::replace_once(sample, "<Id>#x00000E4A</Id>", "<Id>" + std::string(100'000, '9') + "</Id>")},
    };
}

}  // namespace

TEST(HostileGen, ASourceWithErrorsWritesNothing) {
    for (const auto& source : broken_sources()) {
        esi::test::TempDir dir;
        esi::test::write_text(dir / "device.xml", source.text);
        esi::test::write_text(dir / "out" / "keep.h", "previous output\n");
        const auto before = esi::test::snapshot(dir / "out");
        const auto gen = run_child({esi::test::tool("esi-gen").string(), (dir / "device.xml").string(), "-o", (dir / "out").string()});
        EXPECT_EQ(gen.exit_code, 2) << source.name << ": " << gen.err;
        EXPECT_NE(gen.err.find("device.xml:"), std::string::npos) << source.name << ": a located diagnostic\n" << gen.err;
        EXPECT_LT(gen.err.size(), 64u * 1024u) << source.name;
        EXPECT_TRUE(esi::test::snapshot(dir / "out") == before) << source.name << ": the output directory changed";
    }
}

TEST(HostileGen, EntitiesAreNotExpandedIntoGeneratedCode) {
    std::string text = esi::test::sample_esi();
    const auto declaration_end = text.find("?>") + 2;
    text.insert(declaration_end, "\n<!DOCTYPE EtherCATInfo [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;\">]>");
    text = esi::test::replace_once(text, "<Name LcId=\"1033\">EX-DIO-8 8 inputs, 8 outputs</Name>",
                                   "<Name LcId=\"1033\">&b;</Name>");
    esi::test::TempDir dir;
    esi::test::write_text(dir / "device.xml", text);
    const auto gen = run_child({esi::test::tool("esi-gen").string(), (dir / "device.xml").string(), "-o", (dir / "out").string()});
    EXPECT_EQ(gen.exit_code, 0) << gen.err << " (the DOCTYPE is a warning, not an error)";
    EXPECT_NE(gen.err.find("[xml-doctype]"), std::string::npos) << gen.err;
    for (const auto& [name, content] : esi::test::snapshot(dir / "out"))
        EXPECT_EQ(content.find("aaaaaaaaaaaaaaaaaaaa"), std::string::npos) << name << " holds an expanded entity";
}

TEST(HostileDiff, AnUnreadableSideIsExitCodeTwoWithItsPosition) {
    esi::test::TempDir dir;
    const auto sample = (esi::test::source_dir() / "samples/esi/example-digital-io.xml").string();
    for (const auto& source : broken_sources()) {
        esi::test::write_text(dir / "new.xml", source.text);
        const auto diff = run_child({esi::test::tool("esi-diff").string(), sample, (dir / "new.xml").string(), "--format", "json"});
        // A file that parses (deep nesting is cut, numbers are errors in the model) is compared.
        const bool readable = std::string(source.name) == "deep" || std::string(source.name) == "bad-utf8" ||
                              std::string(source.name) == "hex-without-digits" || std::string(source.name) == "huge-number";
        if (readable) {
            EXPECT_TRUE(diff.exit_code == 0 || diff.exit_code == 1) << source.name << ": " << diff.err;
            EXPECT_NE(diff.out.find("\"verdict\""), std::string::npos) << source.name;
        } else {
            EXPECT_EQ(diff.exit_code, 2) << source.name << ": " << diff.out << diff.err;
            EXPECT_NE(diff.err.find("new.xml:"), std::string::npos) << source.name << ": " << diff.err;
        }
        EXPECT_LT(diff.out.size() + diff.err.size(), 256u * 1024u) << source.name;
    }
}
