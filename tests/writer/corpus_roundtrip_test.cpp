// The writer over every well-formed file of ../shared/corpus/esi (skipped where it is absent):
// (a) idempotence: write(read(write(read(x)))) == write(read(x)), byte for byte;
// (b) losslessness: the rewritten XML equals the original as a tree, semantically
//     (xml_tree_compare.hpp), apart from the reader limits listed in known_losses below;
// (c) validity: files MANIFEST.tsv marks "xsd v1.17: valid" stay valid against schema 1.17.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "esi/encoding.hpp"
#include "esi/lint/xsd.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "support/test_support.hpp"
#include "writer/xml_tree_compare.hpp"

namespace {

struct Rewrite {
    std::string file;
    std::string notes;
    bool well_formed = true;  // MANIFEST.tsv does not say NOT WELL-FORMED
    std::string original;     // decoded to UTF-8
    std::string written;      // write(read(original)); empty when reading gave no document
};

// Reads and rewrites the corpus once for all tests of this file.
const std::vector<Rewrite>& all_rewrites() {
    static const std::vector<Rewrite> all = [] {
        std::vector<Rewrite> out;
        for (const auto& [file, notes] : esi::test::corpus_manifest()) {
            const auto path = esi::test::corpus_esi_dir() / file;
            if (path.extension() != ".xml" || !std::filesystem::exists(path)) continue;
            const std::string bytes = esi::test::read_text(path);
            Rewrite r{file, notes, notes.find("NOT WELL-FORMED") == std::string::npos, esi::decode_xml_bytes(bytes).utf8, {}};
            const auto read = esi::read_esi(bytes, file);
            if (read.document) r.written = esi::write_esi(*read.document);
            out.push_back(std::move(r));
        }
        return out;
    }();
    return all;
}

const std::vector<Rewrite>& rewrites() {
    static const std::vector<Rewrite> well_formed = [] {
        std::vector<Rewrite> out;
        for (const auto& r : all_rewrites())
            if (r.well_formed) out.push_back(r);
        return out;
    }();
    return well_formed;
}

// Every file the reader makes a document of, including ones with encoding faults the reader
// repairs (their rewrite is well-formed UTF-8).
TEST(WriterCorpus, RewritingTwiceGivesTheSameBytes) {
    ESI_REQUIRE_CORPUS();
    std::size_t passed = 0;
    std::size_t readable = 0;
    for (const auto& r : all_rewrites()) {
        SCOPED_TRACE(r.file);
        if (r.well_formed) {
            ASSERT_FALSE(r.written.empty()) << "well-formed corpus file was not read";
        }
        if (r.written.empty()) continue;
        ++readable;
        const auto again = esi::read_esi(r.written, r.file + " (rewritten)");
        ASSERT_TRUE(again.document);
        const std::string second = esi::write_esi(*again.document);
        if (second == r.written) {
            ++passed;
            continue;
        }
        const auto at = std::mismatch(second.begin(), second.end(), r.written.begin(), r.written.end());
        const auto offset = static_cast<std::size_t>(at.first - second.begin());
        ADD_FAILURE() << "second rewrite differs at byte " << offset << ": '" << second.substr(offset, 80) << "' vs '"
                      << r.written.substr(offset, 80) << "'";
    }
    std::printf("writer corpus: %zu of %zu readable files (%zu well-formed) rewrite idempotently\n", passed, readable, rewrites().size());
}

// What the tree comparison finds on the corpus and why; every entry is a file that is not
// schema-valid in the first place (docs/esi-writer.md, "Known limits"). A difference not listed
// here fails the test, and so does an entry that no longer occurs.
struct KnownLoss {
    const char* file;
    const char* difference;  // "<kind> <path>[@attribute]" as reported below
    const char* reason;
};
constexpr KnownLoss known_losses[] = {
    {"Beckhoff__EtherCAT_Terminals__dls-ethercat.xml", "attribute added EtherCATInfo/Descriptions/Devices/Device@Physics",
     "Physics is required by the schema and always written; this old file leaves it out"},
    {"Beckhoff__EtherCAT_Terminals__dls-ethercat.xml", "element added EtherCATInfo/Descriptions/Devices/Device/RxPdo/Index",
     "PdoType/Index is required; this old file has <RxPdo Ref=…/> references without one"},
    {"Beckhoff__EtherCAT_Terminals__dls-ethercat.xml", "element added EtherCATInfo/Descriptions/Devices/Device/TxPdo/Index",
     "PdoType/Index is required; this old file has <TxPdo Ref=…/> references without one"},
    {"Beckhoff__CUxxxx__hw_device_mgr.xml", "element added EtherCATInfo/Descriptions/Devices/Device/Profile/Dictionary/Objects",
     "Dictionary/Objects is required and always written; this file has an empty Dictionary"},
    {"PollenRobotics__epos-3axis__poulpe.xml", "element added EtherCATInfo/Descriptions/Groups",
     "Descriptions/Groups is required and always written; this file has none"},
    {"Weidmueller__UR20_FBC_from_IgH__ethercat-esi.xml", "element added EtherCATInfo/Descriptions/Groups",
     "Descriptions/Groups is required and always written; this file has none"},
    {"UTRIO__UC20-RTU-EC-A_20251104__linuxcnc-ethercat.xml", "attribute missing EtherCATInfo/Descriptions/Modules/Module/RxPdo/Entry/Comment@LcId",
     "Entry/Comment is xs:string in the schema and a plain string in the model; its LcId is not kept"},
    {"UTRIO__UC20-RTU-EC-A_20251104__linuxcnc-ethercat.xml", "attribute missing EtherCATInfo/Descriptions/Modules/Module/TxPdo/Entry/Comment@LcId",
     "Entry/Comment is xs:string in the schema and a plain string in the model; its LcId is not kept"},
    {"Copley__XE2_4.60__EtherCAT-ESI-File-Examples__b.xml",
     "element missing EtherCATInfo/Descriptions/Devices/Device/Profile/Dictionary/Objects/Object/Info/SubItem/Info",
     "a SubItem with two Info elements (the schema allows one); the model keeps the last"},
    {"PollenRobotics__epos-3axis__poulpe.xml", "attribute added EtherCATInfo/Descriptions/Devices/Device@Physics",
     "Physics is required by the schema and always written; this file leaves it out"},
    {"Weidmueller__UR20_FBC_from_IgH__ethercat-esi.xml", "attribute added EtherCATInfo/Descriptions/Devices/Device@Physics",
     "Physics is required by the schema and always written; this file leaves it out"},
    {"PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml", "text changed EtherCATInfo/Descriptions/Devices/Device/RxPdo/Entry/Index",
     "'#x0x6041' is not a number (the reader reports xml-number-format); the model holds 0"},
    {"PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml", "text changed EtherCATInfo/Descriptions/Devices/Device/TxPdo/Entry/Index",
     "'#x0x603F' is not a number (the reader reports xml-number-format); the model holds 0"},
    {"PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml", "text changed EtherCATInfo/Descriptions/Devices/Device/RxPdo/Entry/Index",
     "'#x0x6041' is not a number (the reader reports xml-number-format); the model holds 0"},
    {"PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml", "text changed EtherCATInfo/Descriptions/Devices/Device/TxPdo/Entry/Index",
     "'#x0x603F' is not a number (the reader reports xml-number-format); the model holds 0"},
};

std::string difference_key(const esi::test::TreeDifference& d) {
    using Kind = esi::test::TreeDifference::Kind;
    std::string key = std::string(esi::test::to_string(d.kind)) + " " + d.path;
    if (d.kind == Kind::missing_attribute || d.kind == Kind::added_attribute) key += "@" + d.detail;
    if (d.kind == Kind::changed_attribute) key += "@" + d.detail.substr(0, d.detail.find(':'));
    return key;
}

TEST(WriterCorpus, RewrittenTreeEqualsTheOriginal) {
    ESI_REQUIRE_CORPUS();
    std::size_t identical = 0;
    std::size_t only_known = 0;
    std::set<std::pair<std::string, std::string>> seen_known;
    for (const auto& r : rewrites()) {
        SCOPED_TRACE(r.file);
        ASSERT_FALSE(r.written.empty());
        const auto result = esi::test::compare_xml_trees(r.original, r.written, 100000);
        ASSERT_TRUE(result.parsed) << result.error;
        bool unexplained = false;
        for (const auto& d : result.differences) {
            const std::string key = difference_key(d);
            const bool known = std::any_of(std::begin(known_losses), std::end(known_losses),
                                           [&](const KnownLoss& k) { return r.file == k.file && key == k.difference; });
            if (known) {
                seen_known.emplace(r.file, key);
                continue;
            }
            unexplained = true;
            ADD_FAILURE() << "line " << d.line << ": " << key << " " << d.detail;
        }
        if (result.differences.empty()) ++identical;
        else if (!unexplained) ++only_known;
    }
    for (const auto& k : known_losses) {
        if (seen_known.count({k.file, k.difference}) == 0) ADD_FAILURE() << "known loss no longer occurs: " << k.file << ": " << k.difference;
        else std::printf("  known: %s: %s (%s)\n", k.file, k.difference, k.reason);
    }
    std::printf("writer corpus: %zu of %zu well-formed files rewrite without any tree difference, %zu more with only the known "
                "differences above\n",
                identical, rewrites().size(), only_known);
}

TEST(WriterCorpus, SchemaValidFilesStayValid) {
    ESI_REQUIRE_CORPUS();
    esi::Diagnostics load;
    const auto schemas = esi::SchemaSet::load(esi::test::shared_dir() / "corpus/schema/v1.17_siitool-2022", load);
    ASSERT_TRUE(load.empty());
    std::size_t candidates = 0;
    std::size_t passed = 0;
    for (const auto& r : rewrites()) {
        if (r.notes.find("xsd v1.17: valid") == std::string::npos) continue;
        SCOPED_TRACE(r.file);
        ++candidates;
        const auto diagnostics = schemas->validate(esi::SourceText(r.file, r.written));
        if (diagnostics.empty()) {
            ++passed;
            continue;
        }
        for (const auto& d : diagnostics) ADD_FAILURE() << "line " << d.pos.line << ": " << d.message;
    }
    std::printf("writer corpus: %zu of %zu files valid against schema 1.17 stay valid when rewritten\n", passed, candidates);
}

TEST(WriterCorpus, SchemaValidModuleFilesStayValid) {
    // Schema 1.17 has no EtherCATModule.xsd; 1.14 (ETG.2000 1.0.10) is the newest that does.
    ESI_REQUIRE_CORPUS();
    esi::Diagnostics load;
    const auto schemas = esi::SchemaSet::load(esi::test::shared_dir() / "corpus/schema/v1.14_ETG2000-1.0.10", load);
    ASSERT_TRUE(load.empty());
    std::size_t candidates = 0;
    for (const auto& r : rewrites()) {
        if (r.notes.find("root=EtherCATModule") == std::string::npos || r.notes.find("xsd v1.14: valid") == std::string::npos) continue;
        SCOPED_TRACE(r.file);
        ++candidates;
        for (const auto& d : schemas->validate(esi::SourceText(r.file, r.written))) ADD_FAILURE() << "line " << d.pos.line << ": " << d.message;
    }
    EXPECT_GT(candidates, 0u);
    std::printf("writer corpus: %zu module files valid against schema 1.14 checked after rewriting\n", candidates);
}

}  // namespace
