// esi-gen as firmware builds call it: what it writes, that it writes all or nothing, that the
// output does not change between runs, and how templates are overridden.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "codegen_test_support.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

const char* code_kinds = "cpp,c,soes,structs";

TEST(EsiGenCli, WritesEveryCodeOutputOfOneDevice) {
    TempDir dir;
    const auto r = tc::esi_gen(tc::sample_esi(), dir.path(), {"--only", code_kinds});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = tc::tree(dir.path());
    std::vector<std::string> names;
    for (const auto& [name, content] : files) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"ecat_options.h", "object_dictionary.hpp", "objectlist.c", "process_image.h", "slave_tables.c",
                                               "slave_tables.h", "utypes.h"}));
    EXPECT_NE(files.at("object_dictionary.hpp").find("inline constexpr std::uint16_t digital_outputs = 0x7000;"), std::string::npos);
}

TEST(EsiGenCli, TwoRunsAreByteIdentical) {
    TempDir a, b;
    ASSERT_EQ(tc::esi_gen(tc::rich_esi(), a.path(), {"--only", code_kinds}).exit_code, 0);
    ASSERT_EQ(tc::esi_gen(tc::rich_esi(), b.path(), {"--only", code_kinds}).exit_code, 0);
    const auto first = tc::tree(a.path());
    EXPECT_EQ(first.size(), 7u);
    EXPECT_EQ(first, tc::tree(b.path()));
}

TEST(EsiGenCli, SourceWithErrorsWritesNothingAndExitsTwo) {
    TempDir dir;
    write_text(dir / "bad.xml", "<EtherCATInfo>\n<Vendor>\n<Name>x</Name \n</Vendor></EtherCATInfo>\n");
    const auto out = dir.path() / "out";
    write_text(out / "object_dictionary.hpp", "previous");
    const auto r = tc::esi_gen(dir / "bad.xml", out, {"--only", code_kinds});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.xml:3:8: error:"), std::string::npos) << r.err;  // located
    const auto files = tc::tree(out);
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files.at("object_dictionary.hpp"), "previous");
}

TEST(EsiGenCli, BrokenTemplateWritesNothingAndPointsIntoTheTemplate) {
    TempDir dir;
    const auto templates = dir.path() / "templates";
    write_text(templates / "process_image.h.mustache", "ok\n{{#device.objects}}\nunclosed\n");
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(tc::sample_esi(), out, {"--only", code_kinds, "--templates", templates.string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("process_image.h.mustache:2:1: error: Unclosed section"), std::string::npos) << r.err;
    EXPECT_TRUE(tc::tree(out).empty());  // not even the outputs whose templates were fine
}

TEST(EsiGenCli, PartialsInATemplateAreAnErrorAtTheTag) {
    TempDir dir;
    const auto templates = dir.path() / "templates";
    write_text(templates / "soes_utypes.h.mustache", "/* utypes */\n{{#device}}\n  {{> member}}\n{{/device}}\n");
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(tc::sample_esi(), out, {"--only", "soes", "--templates", templates.string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("soes_utypes.h.mustache:3:3: error: partials are not supported"), std::string::npos) << r.err;
    EXPECT_TRUE(tc::tree(out).empty());
}

TEST(EsiGenCli, TemplatesDirOverridesOneTemplateAndKeepsTheOthers) {
    TempDir dir;
    const auto templates = dir.path() / "templates";
    write_text(templates / "ecat_options.h.mustache", "unused: not a template name esi-gen looks for\n");
    write_text(templates / "soes_ecat_options.h.mustache",
               "// {{device.type}} {{device.identity.product_code_hex}}\n{{#device.objects}}{{index_hex}} {{/device.objects}}\n");
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(tc::sample_esi(), out, {"--only", "soes", "--templates", templates.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_text(out / "ecat_options.h"),
              "// EX-DIO-8 0x00001001\n0x1000 0x1018 0x1600 0x1A00 0x1C00 0x1C12 0x1C13 0x6000 0x7000 \n");
    EXPECT_NE(read_text(out / "objectlist.c").find("const _objectlist SDOobjects[]"), std::string::npos);  // built-in
}

TEST(EsiGenCli, StandaloneSectionLinesLeaveNoBlankLines) {
    TempDir dir;
    const auto templates = dir.path() / "templates";
    write_text(templates / "process_image.h.mustache", "a\n{{#device.dc.present}}\n  {{^device.dc.present}}\nnever\n{{/device.dc.present}}\n"
                                                       "{{/device.dc.present}}\n{{! a comment }}\nb\n");
    const auto out = dir.path() / "out";
    ASSERT_EQ(tc::esi_gen(tc::sample_esi(), out, {"--only", "structs", "--templates", templates.string()}).exit_code, 0);
    EXPECT_EQ(read_text(out / "process_image.h"), "a\nb\n");
}

TEST(EsiGenCli, MissingTemplatesDirIsAUsageError) {
    TempDir dir;
    const auto r = tc::esi_gen(tc::sample_esi(), dir.path(), {"--templates", (dir / "nope").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("is not a directory"), std::string::npos);
}

TEST(EsiGenCli, UnknownKindSuggestsTheClosest) {
    TempDir dir;
    const auto r = tc::esi_gen(tc::sample_esi(), dir.path(), {"--only", "cpp,struct"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown output kind 'struct' (did you mean 'structs'?)"), std::string::npos) << r.err;
    EXPECT_TRUE(tc::tree(dir.path()).empty());
}

TEST(EsiGenCli, ListOutputsNamesTheFilesWithoutWriting) {
    TempDir dir;
    const auto out = dir.path() / "gen";
    const auto r = run({tool("esi-gen").string(), tc::sample_esi().string(), "-o", out.string(), "--only", "structs,cpp", "--list-outputs"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, (out / "object_dictionary.hpp").generic_string() + "\n" + (out / "process_image.h").generic_string() + "\n");
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(EsiGenCli, DumpModelPrintsTheView) {
    const auto r = run({tool("esi-gen").string(), tc::sample_esi().string(), "--dump-model", "json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto view = nlohmann::json::parse(r.out);
    EXPECT_EQ(view["devices"][0]["type"], "EX-DIO-8");
    EXPECT_EQ(r.out, read_text(tc::data_dir() / "example-digital-io.view.json"));
}

// Several devices in one file: one directory per device; --device picks one.
class MultiDevice : public ::testing::Test {
protected:
    void SetUp() override {
        std::string xml = read_text(tc::sample_esi());
        const auto start = xml.find("      <Device ");
        const auto end = xml.find("</Device>") + std::string("</Device>").size();
        std::string second = xml.substr(start, end - start);
        const auto rev = second.find("RevisionNo=\"#x00010000\"");
        second.replace(rev, std::string("RevisionNo=\"#x00010000\"").size(), "RevisionNo=\"#x00020000\"");
        xml.insert(end, "\n" + second);
        write_text(dir / "two.xml", xml);
    }
    TempDir dir;
};

TEST_F(MultiDevice, EachDeviceGetsItsOwnDirectory) {
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(dir / "two.xml", out, {"--only", "cpp"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = tc::tree(out);
    ASSERT_EQ(files.size(), 2u);
    // Both revisions share the Type text; the second is told apart by its revision.
    EXPECT_TRUE(files.count("ex_dio_8/object_dictionary.hpp"));
    EXPECT_TRUE(files.count("ex_dio_8_r00020000/object_dictionary.hpp"));
}

TEST_F(MultiDevice, DeviceSelectsOne) {
    const auto out = dir.path() / "out";
    ASSERT_EQ(tc::esi_gen(dir / "two.xml", out, {"--only", "cpp", "--device", "#x1001:#x20000"}).exit_code, 0);
    const auto files = tc::tree(out);
    ASSERT_EQ(files.size(), 1u);
    EXPECT_NE(files.at("object_dictionary.hpp").find("revision 0x00020000"), std::string::npos);
}

TEST_F(MultiDevice, SelectionMatchingNothingIsAUsageError) {
    const auto r = tc::esi_gen(dir / "two.xml", dir.path() / "out", {"--device", "0x9999"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no device matches"), std::string::npos) << r.err;
}

TEST(EsiGenCli, PrefixRenamesTheSymbols) {
    TempDir dir;
    ASSERT_EQ(tc::esi_gen(tc::sample_esi(), dir.path(), {"--only", "c", "--prefix", "board"}).exit_code, 0);
    const std::string header = read_text(dir / "slave_tables.h");
    EXPECT_NE(header.find("board_od_find_entry(uint16_t index, uint8_t subindex)"), std::string::npos);
    EXPECT_NE(header.find("#define BOARD_SLAVE_TABLES_H"), std::string::npos);
}

TEST(EsiGenCli, UsageErrors) {
    EXPECT_EQ(run({tool("esi-gen").string()}).exit_code, 2);
    EXPECT_EQ(run({tool("esi-gen").string(), tc::sample_esi().string()}).exit_code, 2);  // no -o
    EXPECT_EQ(run({tool("esi-gen").string(), tc::sample_esi().string(), "-o", "x", "--device", "nope"}).exit_code, 2);
    const auto kinds = run({tool("esi-gen").string(), "--list-kinds"});
    EXPECT_EQ(kinds.exit_code, 0);
    EXPECT_NE(kinds.out.find("soes\t"), std::string::npos);
}

}  // namespace

namespace {

// The ESI output is the writer's (esi::write_esi); esi-gen must hand it the whole document and
// write it where the plan says.
TEST(EsiGenCliEsi, EsiOutputOfTheSampleIsLintCleanAndSchemaValid) {
    TempDir dir;
    const auto r = tc::esi_gen(tc::sample_esi(), dir.path(), {"--only", "esi"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto written = dir / "example-digital-io.xml";
    ASSERT_TRUE(std::filesystem::exists(written));
    const auto lint = run({tool("esi-lint").string(), written.string()});
    EXPECT_EQ(lint.exit_code, 0) << lint.out;
    EXPECT_NE(lint.out.find("0 errors, 0 warnings, 0 infos in 1 file"), std::string::npos) << lint.out;

    const auto xsd = esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022" / "EtherCATInfo.xsd";
    if (!std::filesystem::exists(xsd) || !tc::have_program("xmllint")) GTEST_SKIP() << "no ETG schema or xmllint: schema check skipped";
    const auto valid = run({"xmllint", "--noout", "--schema", xsd.string(), written.string()});
    EXPECT_EQ(valid.exit_code, 0) << valid.err;
}

TEST(EsiGenCliEsi, RefusesToOverwriteTheSource) {
    TempDir dir;
    write_text(dir / "device.xml", read_text(tc::sample_esi()));
    const auto r = tc::esi_gen(dir / "device.xml", dir.path(), {"--only", "esi,cpp"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("is the source file itself"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(dir / "device.xml"), read_text(tc::sample_esi()));
    EXPECT_FALSE(std::filesystem::exists(dir / "object_dictionary.hpp"));
}

}  // namespace
