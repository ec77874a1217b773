// esi-gen --import as users call it: ESI -> YAML -> esi-gen -> esi-diff finds nothing; malformed
// input is exit 2 with its xml-syntax position and writes nothing; --device selects; the output
// is byte-identical on a re-run.

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string sample_esi() { return (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string(); }

// import, regenerate, diff; returns the esi-diff run.
esi::test::RunResult import_generate_diff(const std::string& esi, const TempDir& dir) {
    const auto yaml = (dir / "source.yaml").string();
    const auto imported = run({tool("esi-gen"), "--import", esi, "-o", yaml});
    EXPECT_EQ(imported.exit_code, 0) << imported.err;
    const auto generated = run({tool("esi-gen"), yaml, "-o", (dir / "out").string(), "--only", "esi"});
    EXPECT_EQ(generated.exit_code, 0) << generated.err;
    std::string xml;
    for (const auto& e : std::filesystem::directory_iterator(dir / "out"))
        if (e.path().extension() == ".xml") xml = e.path().string();
    EXPECT_FALSE(xml.empty());
    return run({tool("esi-diff"), esi, xml, "--fail-on", "any"});
}

TEST(ImportCli, SampleRoundTripsThroughEsiGenAndEsiDiff) {
    TempDir dir;
    const auto diff = import_generate_diff(sample_esi(), dir);
    EXPECT_EQ(diff.exit_code, 0) << diff.out << diff.err;
    EXPECT_NE(diff.out.find("identical"), std::string::npos) << diff.out;
}

TEST(ImportCli, CorpusFilesRoundTripThroughEsiGenAndEsiDiff) {
    ESI_REQUIRE_CORPUS();
    for (const char* file : {"ABT__EasyCAT_V2_0__soes.xml", "Beckhoff__EL1xxx__dls-ethercat__2011-08.xml"}) {
        SCOPED_TRACE(file);
        const auto path = esi::test::corpus_esi_dir() / file;
        ASSERT_TRUE(std::filesystem::exists(path));
        TempDir dir;
        const auto diff = import_generate_diff(path.string(), dir);
        EXPECT_EQ(diff.exit_code, 0) << diff.out << diff.err;
    }
}

TEST(ImportCli, MalformedInputExitsTwoAndWritesNothing) {
    TempDir dir;
    write_text(dir / "bad.xml", "<EtherCATInfo>\n<Vendor>\n<Name>x</Name \n</Vendor></EtherCATInfo>\n");
    const auto r = run({tool("esi-gen"), "--import", (dir / "bad.xml").string(), "-o", (dir / "source.yaml").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.xml:3:8: error: not well-formed"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[xml-syntax]"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "source.yaml"));
    EXPECT_EQ(run({tool("esi-gen"), "--import", "/nonexistent/x.xml", "-o", (dir / "s.yaml").string()}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-gen"), "--import", sample_esi()}).exit_code, 2);  // no -o
    EXPECT_FALSE(std::filesystem::exists(dir / "s.yaml"));
}

TEST(ImportCli, DeviceSelectsAndOutputIsDeterministic) {
    TempDir dir;
    const auto first = run({tool("esi-gen"), "--import", sample_esi(), "-o", (dir / "a.yaml").string()});
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const auto second = run({tool("esi-gen"), "--import", sample_esi(), "-o", (dir / "b.yaml").string()});
    ASSERT_EQ(second.exit_code, 0) << second.err;
    EXPECT_EQ(read_text(dir / "a.yaml"), read_text(dir / "b.yaml"));

    const auto one = run({tool("esi-gen"), "--import", sample_esi(), "-o", (dir / "one.yaml").string(), "--device", "#x00001001"});
    EXPECT_EQ(one.exit_code, 0) << one.err;
    EXPECT_NE(read_text(dir / "one.yaml").find("product_code: 0x00001001"), std::string::npos);
    const auto none = run({tool("esi-gen"), "--import", sample_esi(), "-o", (dir / "c.yaml").string(), "--device", "#x7777777"});
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_NE(none.err.find("[import-device]"), std::string::npos) << none.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "c.yaml"));
    EXPECT_EQ(run({tool("esi-gen"), "--import", sample_esi(), "-o", (dir / "d.yaml").string(), "--device", "x:y"}).exit_code, 2);
}

}  // namespace
