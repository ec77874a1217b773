// Code generation over the real vendor files: every device renders every template, and the SOES
// object list generated from a SOES demo's ESI has the structure of the object list SOES ships
// with that demo (applications/linux_lan9252demo/slave_objectlist.c).

#include <gtest/gtest.h>

#include "codegen_test_support.hpp"
#include "esi/codegen/generate.hpp"
#include "esi/codegen/template_lookup.hpp"
#include "esi/xml/reader.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::read_text;
using esi::test::TempDir;
using esi::test::write_text;

esi::codegen::GenerateOptions code_options() {
    esi::codegen::GenerateOptions options;
    options.output_dir = "out";
    options.only = {"cpp", "c", "soes", "structs"};
    options.template_dirs = esi::codegen::template_search_path({}, std::nullopt);
    return options;
}

TEST(CorpusCodegen, EveryDeviceOfEveryReadableFileRenders) {
    ESI_REQUIRE_CORPUS();
    std::size_t files = 0, devices = 0;
    for (const auto& [name, notes] : esi::test::corpus_manifest()) {
        const auto read = esi::read_esi_file(esi::test::corpus_esi_dir() / name);
        if (!read.document || read.diagnostics.has_errors()) continue;  // the reader's findings, tested elsewhere
        bool has_device = false;
        for (const auto& info : read.document->infos) has_device = has_device || !info.devices.empty();
        if (!has_device) continue;  // dictionary-only files
        const auto result = esi::codegen::generate_outputs(*read.document, code_options());
        for (const auto& d : result.diagnostics)
            EXPECT_NE(d.severity, esi::Severity::error) << name << ": " << d.message;
        EXPECT_FALSE(result.files.empty()) << name;
        for (const auto& f : result.files) EXPECT_FALSE(f.content.empty()) << name << " " << f.path;
        ++files;
        devices += result.files.size() / 7;
    }
    EXPECT_GT(files, 50u);
    EXPECT_GT(devices, 500u);
}

TEST(CorpusCodegen, LargeFilesRenderTheSameTwice) {
    ESI_REQUIRE_CORPUS();
    for (const char* name : {"Beckhoff__EL3xxx__dls-ethercat.xml", "SOES__rtl_xmc4_dynpdo__soes.xml"}) {
        const auto read = esi::read_esi_file(esi::test::corpus_esi_dir() / name);
        ASSERT_TRUE(read.document) << name;
        const auto a = esi::codegen::generate_outputs(*read.document, code_options());
        const auto b = esi::codegen::generate_outputs(*read.document, code_options());
        ASSERT_EQ(a.files.size(), b.files.size());
        for (std::size_t k = 0; k < a.files.size(); ++k) {
            EXPECT_EQ(a.files[k].path, b.files[k].path);
            EXPECT_EQ(a.files[k].content, b.files[k].content) << a.files[k].path;
        }
    }
}

// Facts of SOES's hand-maintained list for the same demo: index, object code, max sub-index,
// and the values of the constants.
TEST(CorpusCodegen, SoesDemoObjectListMatchesTheOneSoesShips) {
    ESI_REQUIRE_CORPUS();
    TempDir dir;
    const auto r = tc::esi_gen(esi::test::corpus_esi_dir() / "SOES__linux_lan9252demo__soes.xml", dir.path(), {"--only", "soes"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string list = read_text(dir / "objectlist.c");
    for (const char* line : {"{ 0x1000, OTYPE_VAR, 0, 0, acName1000, SDO1000 }", "{ 0x1008, OTYPE_VAR, 0, 0, acName1008, SDO1008 }",
                             "{ 0x1018, OTYPE_RECORD, 4, 0, acName1018, SDO1018 }", "{ 0x1600, OTYPE_RECORD, 2, 0, acName1600, SDO1600 }",
                             "{ 0x1A00, OTYPE_RECORD, 1, 0, acName1A00, SDO1A00 }", "{ 0x1C00, OTYPE_ARRAY, 4, 0, acName1C00, SDO1C00 }",
                             "{ 0x1C12, OTYPE_ARRAY, 1, 0, acName1C12, SDO1C12 }", "{ 0x1C13, OTYPE_ARRAY, 1, 0, acName1C13, SDO1C13 }",
                             "{ 0x6000, OTYPE_RECORD, 1, 0, acName6000, SDO6000 }", "{ 0x7000, OTYPE_RECORD, 2, 0, acName7000, SDO7000 }",
                             "{ 0x8000, OTYPE_RECORD, 1, 0, acName8000, SDO8000 }", "{ 0xffff, 0xff, 0xff, 0xff, NULL, NULL }"})
        EXPECT_NE(list.find(line), std::string::npos) << line;
    for (const char* line : {"ATYPE_RO, acName1000_00, 0x01901389, NULL }", "ATYPE_RO, acName1018_01, 0x00001337, NULL }",
                             "ATYPE_RO, acName1600_01, 0x70000108, NULL }", "ATYPE_RO, acName1C13_01, 0x1A00, NULL }",
                             "{ 0x00, DTYPE_VISIBLE_STRING, 88, ATYPE_RO, acName1008_00, 0, \"evb9252_dig\" }",
                             // PDO-mapped entries live in Obj even though the ESI flags them only ro.
                             "acName6000_01, 0x00, &Obj.buttons.button1 }", "acName7000_02, 0x00, &Obj.leds.led1 }",
                             "ATYPE_RW, acName8000_01, 0x00000000, &Obj.parameters.multiplier }"})
        EXPECT_NE(list.find(line), std::string::npos) << line;

    ESI_REQUIRE_COMPILERS();
    write_text(dir / "main.c", "#include \"esc_coe.h\"\n#include \"utypes.h\"\n_Objects Obj;\n"
                               "int main(void) { return SDOobjects[12].index == 0x8000 && SDOobjects[13].index == 0xffff ? 0 : 1; }\n");
    const auto exe = dir.path() / "soes_demo";
    const auto c = tc::compile("cc", "c99", {"-I" + dir.path().string(), "-I" + tc::soes_stand_in_dir().string(),
                                             (dir / "objectlist.c").string(), (dir / "main.c").string()},
                               exe);
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_EQ(esi::test::run({exe.string()}).exit_code, 0);
}

// Drives and terminals with bit fields, padding and many objects: their code compiles.
TEST(CorpusCodegen, SelectedVendorFilesCompile) {
    ESI_REQUIRE_CORPUS();
    ESI_REQUIRE_COMPILERS();
    for (const auto& [file, device] : std::vector<std::pair<std::string, std::string>>{
             {"Beckhoff__EL3xxx__dls-ethercat.xml", "#x0E123052:#x00100000"},  // EL3602: BOOL/BIT2 status bits, padding
             {"SOES__rtl_xmc4_dynpdo__soes.xml", ""},
             {"MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-10.xml", ""}}) {
        TempDir dir;
        std::vector<std::string> extra{"--only", "cpp,c,soes,structs"};
        if (!device.empty()) extra.insert(extra.end(), {"--device", device});
        const auto r = tc::esi_gen(esi::test::corpus_esi_dir() / file, dir.path(), extra);
        ASSERT_EQ(r.exit_code, 0) << file << r.err;
        const std::string inc = "-I" + dir.path().string();
        write_text(dir / "all.cpp", "#include \"object_dictionary.hpp\"\n#include \"process_image.h\"\n#include \"slave_tables.h\"\n");
        EXPECT_EQ(tc::compile("c++", "c++17", {inc, (dir / "all.cpp").string()}).exit_code, 0) << file;
        EXPECT_EQ(tc::compile("cc", "c99", {inc, (dir / "slave_tables.c").string()}).exit_code, 0) << file;
        EXPECT_EQ(tc::compile("cc", "c99", {inc, "-I" + tc::soes_stand_in_dir().string(), (dir / "objectlist.c").string()}).exit_code, 0)
            << file;
    }
}

}  // namespace
