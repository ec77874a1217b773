// A vendor ESI turned into a YAML source and back into everything esi-gen makes, with the default
// outputs (SII image included): `esi-gen --import X -o s.yaml && esi-gen s.yaml -o out` for
// every well-formed EtherCATInfo file of ../shared/corpus/esi. The files that cannot go through
// are listed with the reason (docs/sii.md §5, docs/yaml-import.md); any other failure fails the
// test, and so does a listed file that goes through now.

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "codegen_test_support.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;

const std::map<std::string, std::string>& known_exceptions() {
    static const std::map<std::string, std::string> list = {
        // The YAML source cannot express these files (docs/yaml-import.md, "Known exceptions").
        {"Beckhoff__EL2xxx__dls-ethercat.xml", "a device lists RxPdo #x1602 twice"},
        {"Beckhoff__EtherCAT_Terminals__dls-ethercat.xml", "an RxPdo without Index (the reader reports an error)"},
        {"PollenRobotics__epos-3axis__poulpe.xml", "three devices share one identity (refused, naming both places)"},
        {"PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml", "Index '#x0x6041' is not a number"},
        {"PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml", "Index '#x0x6041' is not a number"},
        // The declared EEPROM cannot hold even the mandatory part of the image (docs/sii.md §5).
        {"Beckhoff__EtherCAT_EvaBoard__dls-ethercat.xml", "16 of the 19 boards declare 128 bytes, the size of the header alone"},
    };
    return list;
}

std::string first_error(const std::string& err) {
    const auto at = err.find(": error: ");
    if (at == std::string::npos) return err.substr(0, 300);
    const auto start = err.rfind('\n', at);
    const auto end = err.find('\n', at);
    return err.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1));
}

TEST(ImportGenerateCorpus, EveryVendorFileImportsAndGeneratesWithTheDefaultOutputs) {
    ESI_REQUIRE_CORPUS();
    std::size_t total = 0, passed = 0;
    for (const auto& [file, notes] : esi::test::corpus_manifest()) {
        const bool info_root = notes.find("root=EtherCATInfo ") != std::string::npos || notes.find("root=EtherCATInfo;") != std::string::npos;
        if (notes.find("NOT WELL-FORMED") != std::string::npos || !info_root) continue;
        const auto path = esi::test::corpus_esi_dir() / file;
        if (!std::filesystem::exists(path)) continue;
        ++total;
        TempDir dir;
        const auto source = dir.path() / "s.yaml";
        std::string failure;
        const auto imported = run({tool("esi-gen").string(), "--import", path.string(), "-o", source.string()});
        if (imported.exit_code != 0) {
            failure = "import: " + first_error(imported.err);
        } else {
            const auto generated = tc::esi_gen(source, dir.path() / "out");
            if (generated.exit_code != 0) failure = "generate: " + first_error(generated.err);
            else if (tc::tree(dir.path() / "out").empty()) failure = "generate: nothing written";
        }
        const auto listed = known_exceptions().find(file);
        if (failure.empty()) {
            ++passed;
            if (listed != known_exceptions().end()) ADD_FAILURE() << file << " goes through now; remove it from known_exceptions";
            continue;
        }
        std::printf("import -> generate: %s: %s\n", file.c_str(), failure.c_str());
        if (listed == known_exceptions().end()) ADD_FAILURE() << file << ": " << failure;
    }
    std::printf("import -> generate: %zu of %zu EtherCATInfo corpus files go through with the default outputs (%zu listed "
                "exceptions)\n",
                passed, total, known_exceptions().size());
    EXPECT_GT(total, 0u);
}

}  // namespace
