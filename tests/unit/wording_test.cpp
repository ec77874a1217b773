// Counts in messages and pages read as English: "1 byte", "3 bytes" (esi::counted), never
// "1 bytes" or "1 commands". Every message template is checked:
//  - the page and code templates (templates/**/*.mustache) may not put a number field right
//    before a plural noun; they use the views' *_text fields, made by esi::counted;
//  - the library's and tools' message templates ("{} bytes", to_string(n) + " bytes") are
//    counted per file. The sites that existed when the check came in are listed below (most
//    print sizes that cannot be 1: EEPROM sizes, category lengths); a new one fails, and one
//    converted to esi::counted lowers its file's number here.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "esi/plural.hpp"
#include "esi/xml/reader.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

const std::string nouns = "(bytes|bits|commands|entries|objects|pages|frames|PDOs|devices|strings|files|errors|warnings|categories|words)";

std::vector<std::string> lines_of(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

}  // namespace

TEST(Wording, CountedPicksSingularOrPlural) {
    EXPECT_EQ(esi::counted(1, "byte"), "1 byte");
    EXPECT_EQ(esi::counted(0, "byte"), "0 bytes");
    EXPECT_EQ(esi::counted(2, "byte"), "2 bytes");
    EXPECT_EQ(esi::counted(1, "entry", "entries"), "1 entry");
    EXPECT_EQ(esi::counted(7, "entry", "entries"), "7 entries");
    EXPECT_EQ(esi::counted(1, "device page"), "1 device page");
}

TEST(Wording, NoTemplatePutsANumberFieldBeforeAPluralNoun) {
    const std::regex number_then_noun("\\{\\{[^}#^/!>]*\\}\\}\\s*" + nouns + "\\b");
    std::size_t templates = 0;
    for (const auto& entry : fs::recursive_directory_iterator(esi::test::source_dir() / "templates")) {
        if (entry.path().extension() != ".mustache") continue;
        ++templates;
        const auto lines = lines_of(entry.path());
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (std::regex_search(lines[i], number_then_noun))
                ADD_FAILURE() << entry.path().string() << ":" << i + 1 << ": a number field before a plural noun (\"1 bytes\"); "
                              << "use a *_text field made by esi::counted\n    " << lines[i];
    }
    EXPECT_GT(templates, 5u);
}

TEST(Wording, MessageTemplatesWithACountBeforeAPluralNounDoNotGrow) {
    // file -> sites when the check came in.
    const std::map<std::string, std::size_t> known = {
        {"cli/esi-sii.cpp", 1},
        {"libesi/src/check/rules_initcmd.cpp", 2},
        {"libesi/src/check/rules_pdo_default.cpp", 1},
        {"libesi/src/check/rules_profile.cpp", 3},
        {"libesi/src/check/rules_sm.cpp", 1},
        {"libesi/src/derive/pdo_entries.cpp", 1},
        {"libesi/src/derive/sync_managers.cpp", 2},
        {"libesi/src/diff/compare_data_types.cpp", 4},
        {"libesi/src/diff/compare_eeprom.cpp", 1},
        {"libesi/src/diff/compare_pdos.cpp", 5},
        {"libesi/src/diff/recorder.cpp", 2},
        {"libesi/src/doc/section_process_data.cpp", 1},
        {"libesi/src/import/import_common.cpp", 1},
        {"libesi/src/net/coe_init_cmds.cpp", 1},
        {"libesi/src/net/map_writer.cpp", 1},
        {"libesi/src/net/pdo_entries.cpp", 3},
        {"libesi/src/net/process_image.cpp", 1},
        {"libesi/src/net/resolve.cpp", 2},
        {"libesi/src/net/sync_setup.cpp", 3},
        {"libesi/src/sii/build.cpp", 9},
        {"libesi/src/sii/build_categories.cpp", 4},
        {"libesi/src/sii/check.cpp", 3},
        {"libesi/src/sii/decode.cpp", 24},
        {"libesi/src/sii/image_file.cpp", 2},
        {"libesi/src/sii/render.cpp", 16},
        {"libesi/src/yaml/source.cpp", 2},
    };
    const std::regex placeholder("\\{\\}\\s+" + nouns + "\\b");
    const std::regex concatenated("to_string\\([^()]*(\\([^()]*\\))?[^()]*\\)\\s*\\+\\s*\"\\s+" + nouns + "\\b");
    const fs::path root = esi::test::source_dir();
    std::map<std::string, std::size_t> found;
    for (const char* dir : {"libesi/src", "cli"}) {
        for (const auto& entry : fs::recursive_directory_iterator(root / dir)) {
            const auto ext = entry.path().extension();
            if (ext != ".cpp" && ext != ".hpp") continue;
            const std::string name = entry.path().lexically_relative(root).generic_string();
            for (const auto& line : lines_of(entry.path())) {
                // std::regex is slow: only lines that can match go through it.
                if (line.find("{}") == std::string::npos && line.find("to_string(") == std::string::npos) continue;
                if (line.find_first_not_of(' ') != std::string::npos && line.compare(line.find_first_not_of(' '), 2, "//") == 0)
                    continue;
                const auto count = [&](const std::regex& r) {
                    return static_cast<std::size_t>(std::distance(std::sregex_iterator(line.begin(), line.end(), r), std::sregex_iterator()));
                };
                if (const std::size_t n = count(placeholder) + count(concatenated)) found[name] += n;
            }
        }
    }
    for (const auto& [file, n] : found) {
        const auto it = known.find(file);
        const std::size_t allowed = it == known.end() ? 0 : it->second;
        EXPECT_LE(n, allowed) << file << ": a new message puts a count before a plural noun (\"{} bytes\"); use esi::counted";
        if (n < allowed) ADD_FAILURE() << file << ": " << allowed - n << " site(s) converted; lower its number in this test to " << n;
    }
    for (const auto& [file, n] : known)
        if (!found.count(file)) ADD_FAILURE() << file << ": no site left; remove it from this test";
}

TEST(Wording, NotANumberIsNotSaidTwice) {
    const std::string xml =
        "<EtherCATInfo><Vendor><Id>#xZZ</Id><Name>V</Name></Vendor><Descriptions><Groups/><Devices/></Descriptions></EtherCATInfo>";
    const esi::ReadResult r = esi::read_esi(xml, "bad.xml");
    std::string text;
    for (const auto& d : r.diagnostics) text += d.message + "\n";
    EXPECT_NE(text.find("is not a number"), std::string::npos) << text;
    EXPECT_EQ(text.find("(not a number)"), std::string::npos) << text;
}
