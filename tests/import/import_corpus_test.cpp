// esi-gen --import over the corpus (issue 4 §3): for every well-formed file of
// ../shared/corpus/esi with an EtherCATInfo root, import -> YAML text -> load_device_source ->
// write_esi -> read_esi -> diff_documents(original, regenerated) must find no change at all, not
// even a cosmetic one. Files that cannot round-trip are listed in known_exceptions with the
// reason (docs/yaml-import.md); any other failure fails the test, and so does a listed file that
// round-trips now (so the list cannot go stale).

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>

#include "esi/diff/classification.hpp"
#include "esi/diff/diff.hpp"
#include "esi/import/import.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "esi/yaml/source.hpp"
#include "support/test_support.hpp"

namespace {

// File -> why it cannot round-trip (docs/yaml-import.md, "Known exceptions").
const std::map<std::string, std::string>& known_exceptions() {
    static const std::map<std::string, std::string> list = {
        {"Beckhoff__EL2xxx__dls-ethercat.xml",
         "a device lists RxPdo #x1602 twice; in the YAML source a PDO index is one PDO (yaml-duplicate)"},
        {"Beckhoff__EtherCAT_Terminals__dls-ethercat.xml",
         "a device uses one index for an RxPdo and a TxPdo; in the YAML source an index is one PDO (yaml-duplicate)"},
        {"PollenRobotics__epos-3axis__poulpe.xml",
         "three devices share ProductCode #x69500000 and RevisionNo #x01700000; the YAML source declares an identity once"},
        {"PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml",
         "PDO entries write their Index as '#x0x6041', which is not a number (the reader reports xml-number-format); the value is lost on reading"},
        {"PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml",
         "PDO entries write their Index as '#x0x6041', which is not a number (the reader reports xml-number-format); the value is lost on reading"},
        {"ProjectMARCH__BP-GES__ethercat-slaves__2020-03.xml",
         "the dictionary declares object #x1A00 and DataType DT1A00 twice; YAML keys (object indices, type names) are unique"},
    };
    return list;
}

struct Outcome {
    bool ok = false;
    std::string failure;  // stage and first difference
    std::size_t devices = 0;
    std::size_t derived_devices = 0;
};

Outcome round_trip(const std::string& file, const std::string& bytes) {
    Outcome out;
    const esi::ReadResult original = esi::read_esi(bytes, file);
    if (!original.document) return {false, "not read"};
    const esi::ImportResult imported = esi::import_device_source(*original.document);
    if (!imported.yaml) {
        out.failure = "import failed";
        for (const auto& d : imported.diagnostics) out.failure += ": " + d.message;
        return out;
    }
    out.devices = imported.devices;
    out.derived_devices = imported.derived_devices;
    const esi::DeviceSource loaded = esi::load_device_source(*imported.yaml, file + ".yaml");
    if (!loaded.document) {
        out.failure = "YAML not loaded";
        for (const auto& d : loaded.diagnostics)
            if (d.severity == esi::Severity::error) {
                out.failure += ": " + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.message + " [" + d.rule + "]";
                break;
            }
        return out;
    }
    const std::string xml = esi::write_esi(*loaded.document);
    const esi::ReadResult regenerated = esi::read_esi(xml, file + ".regenerated.xml");
    if (!regenerated.document) return {false, "regenerated XML not read"};
    const esi::DiffResult diff = esi::diff_documents(*original.document, *regenerated.document);
    if (diff.identical()) {
        out.ok = true;
        return out;
    }
    const esi::Change& first = diff.changes.front();
    out.failure = std::to_string(diff.changes.size()) + " change(s), first " + std::string(esi::to_string(first.kind)) + " at " +
                  first.path + ": " + first.message;
    return out;
}

// The corpus is taken in four quarters (every fourth file), four tests that ctest can run side by
// side: whole, this is the suite's longest test, and several minutes under the sanitizers.
constexpr int corpus_quarters = 4;

class ImportCorpusQuarter : public ::testing::TestWithParam<int> {};

TEST_P(ImportCorpusQuarter, EveryEtherCATInfoFileRoundTrips) {
    ESI_REQUIRE_CORPUS();
    int file_index = -1;
    std::size_t total = 0;
    std::size_t passed = 0;
    std::size_t devices = 0;
    std::size_t derived = 0;
    std::set<std::string> failed_listed;
    for (const auto& [file, notes] : esi::test::corpus_manifest()) {
        const bool info_root = notes.find("root=EtherCATInfo ") != std::string::npos || notes.find("root=EtherCATInfo;") != std::string::npos;
        if (notes.find("NOT WELL-FORMED") != std::string::npos || !info_root) continue;
        const auto path = esi::test::corpus_esi_dir() / file;
        if (!std::filesystem::exists(path)) continue;
        if (++file_index % corpus_quarters != GetParam()) continue;
        ++total;
        const Outcome o = round_trip(file, esi::test::read_text(path));
        const auto listed = known_exceptions().find(file);
        if (o.ok) {
            ++passed;
            devices += o.devices;
            derived += o.derived_devices;
            if (listed != known_exceptions().end())
                ADD_FAILURE() << file << " round-trips now; remove it from known_exceptions";
            continue;
        }
        std::printf("import round trip: %s: %s\n", file.c_str(), o.failure.c_str());
        if (listed == known_exceptions().end()) ADD_FAILURE() << file << ": " << o.failure;
        else failed_listed.insert(file);
    }
    std::printf("import round trip: %zu of %zu EtherCATInfo corpus files round-trip without any change (%zu known exceptions)\n",
                passed, total, failed_listed.size());
    std::printf("import round trip: of the %zu devices in those files, %zu leave at least one part to derivation\n", devices, derived);
    EXPECT_GT(total, 0u);
}

INSTANTIATE_TEST_SUITE_P(Quarter, ImportCorpusQuarter, ::testing::Range(0, corpus_quarters));

}  // namespace
