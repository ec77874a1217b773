// esi-diff on YAML device sources (issue 22): two revisions of a source are compared on the
// models they describe, as two ESI files are; either side may come from standard input.

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::filesystem::path sample() { return esi::test::source_dir() / "samples" / "digital-io-8.yaml"; }

TEST(EsiDiffYaml, ASourceAgainstItselfIsIdentical) {
    const auto r = run({tool("esi-diff"), sample().string(), sample().string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("identical (no changes)"), std::string::npos) << r.out;
    EXPECT_EQ(r.err.find("text before the root element"), std::string::npos) << r.err;
}

TEST(EsiDiffYaml, ARevisionOfTheSourceIsClassified) {
    TempDir dir;
    std::string text = read_text(sample());
    const std::string old_code = "product_code: 0x00001002";
    const auto at = text.find(old_code);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, old_code.size(), "product_code: 0x00001003");
    write_text(dir / "new.yaml", text);
    const auto r = run({tool("esi-diff"), sample().string(), (dir / "new.yaml").string()});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // the device the old file described is gone
    EXPECT_NE(r.out.find("breaking"), std::string::npos) << r.out;

    // The old revision piped in, as `git show REV:device.yaml | esi-diff - device.yaml` does.
    const auto piped = run({tool("esi-diff"), "-", (dir / "new.yaml").string()}, read_text(sample()));
    EXPECT_EQ(piped.exit_code, 1) << piped.out << piped.err;
    EXPECT_NE(piped.out.find("breaking"), std::string::npos) << piped.out;
}

TEST(EsiDiffYaml, ASourceWithAnErrorIsUnusableInput) {
    TempDir dir;
    write_text(dir / "bad.yaml", "vendor: { id: 0x10, name: Example }\ndevices:\n  - type: D\n    nmae: x\n");
    const auto r = run({tool("esi-diff"), (dir / "bad.yaml").string(), sample().string()});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("bad.yaml:4:5: error: "), std::string::npos) << r.err;
}

TEST(EsiDiffYaml, AnEniIsNamedAsSuch) {
    TempDir dir;
    write_text(dir / "network.xml", "<EtherCATConfig><Config/></EtherCATConfig>\n");
    const auto r = run({tool("esi-diff"), (dir / "network.xml").string(), sample().string()});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("not an ESI file (an ENI"), std::string::npos) << r.err;
}

}  // namespace
