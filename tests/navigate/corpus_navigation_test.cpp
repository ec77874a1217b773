// Navigation on vendor ESI files of the corpus: exact answers on one catalogue, and on every
// file that each PDO entry's definition is an object whose references lead back to the entry.

#include <gtest/gtest.h>

#include <filesystem>

#include "esi/encoding.hpp"
#include "navigate/navigate_test_support.hpp"
#include "support/test_support.hpp"

namespace esi::navigate {
namespace {

// As an editor holds it: decoded to UTF-8.
std::string corpus_text(const std::string& name) {
    return decode_xml_bytes(esi::test::read_text(esi::test::corpus_esi_dir() / name)).utf8;
}

TEST(CorpusNavigation, El3xxxEntryOfTheFirstDevice) {
    if (!esi::test::have_shared_corpus()) GTEST_SKIP() << "the shared corpus (../shared) is absent";
    const std::string text = corpus_text("Beckhoff__EL3xxx__dls-ethercat.xml");
    const auto index = build_index(text, "EL3xxx.xml");
    // EL3602's first TxPdo entry maps #x6000:01 (Underrange).
    const std::size_t pdo = text.find("<TxPdo");
    ASSERT_NE(pdo, std::string::npos);
    const std::size_t entry_index = text.find("<Index>#x6000", pdo) + 7;
    ASSERT_LT(text.substr(entry_index, 60).find("<SubIndex>1</SubIndex>"), 40u) << text.substr(entry_index, 60);
    const LineMap lines(text);
    const Position cursor = lines.position_of(entry_index + 2);
    const auto result = hover(*index, cursor);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->range, lines.range_of(entry_index, entry_index + 6));
    EXPECT_EQ(result->markdown,
              "**#x6000:01 Underrange**  \nsub-item of #x6000 AI Inputs Ch.1\n\n- type: `BOOL`\n- size: 1 bit\n"
              "- bit offset: 16\n- access: ro\n- PDO mapping: T\n- default: `00`\n");
    const auto found = definition(*index, cursor);
    ASSERT_EQ(found.size(), 1u);
    // The Name of SubItem 1 in the DataType of EL3602's #x6000, before the entry, in EL3602.
    const std::size_t target = *lines.offset_of(found[0].range.start);
    EXPECT_LT(target, entry_index);
    EXPECT_EQ(text.substr(target, 10), "Underrange");
    const auto symbols = outline(*index);
    ASSERT_EQ(symbols.size(), 37u);
    EXPECT_EQ(symbols[0].name, "EL3602");
    EXPECT_EQ(symbols[0].detail, "EL3602 2Ch. Ana. Input +/-10Volt, Diff. 24bit");
}

TEST(CorpusNavigation, EveryEntryLeadsToItsObjectAndBack) {
    if (!esi::test::have_shared_corpus()) GTEST_SKIP() << "the shared corpus (../shared) is absent";
    std::size_t files = 0;
    std::size_t checked = 0;
    for (const auto& file : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (file.path().extension() != ".xml") continue;
        ++files;
        const std::string text = decode_xml_bytes(esi::test::read_text(file.path())).utf8;
        const auto index = build_index(text, file.path().string());
        const LineMap lines(text);
        // The first entries of each file (references walk the whole file; a few per file keep
        // the test short).
        std::size_t in_file = 0;
        for (const Symbol& device : outline(*index)) {
            for (const Symbol& pdo : device.children) {
                if (pdo.kind != SymbolKind::pdo || pdo.children.empty() || in_file >= 4) continue;
                const Symbol& entry = pdo.children.front();
                if (entry.name == "padding") continue;
                const auto found = definition(*index, entry.selection_range.start);
                if (found.empty()) continue;  // a vendor file may map an object it does not describe
                ++in_file;
                ++checked;
                EXPECT_TRUE(hover(*index, entry.selection_range.start)) << file.path() << " " << entry.name;
                // From the object's Index (not the sub-item) the entry is among the references.
                const auto object = std::find_if(device.children.begin(), device.children.end(), [&](const Symbol& s) {
                    return s.kind == SymbolKind::object && s.name == entry.name.substr(0, entry.name.find(':'));
                });
                if (object == device.children.end()) continue;
                const auto uses = references(*index, object->selection_range.start, false);
                EXPECT_NE(std::find_if(uses.begin(), uses.end(),
                                       [&](const Location& l) { return l.range == entry.selection_range; }),
                          uses.end())
                    << file.path() << " " << entry.name;
            }
        }
    }
    EXPECT_GT(files, 50u);
    EXPECT_GT(checked, 100u);
}

}  // namespace
}  // namespace esi::navigate
