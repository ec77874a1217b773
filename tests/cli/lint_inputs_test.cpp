// What esi-lint accepts besides ESI files (issue 22): YAML device sources, linted on the model
// they describe with positions in the YAML; XML files that are not ESI (an ENI, an lcec
// configuration) skipped with a note on a directory walk and an error when named; a config
// file with an error stopping the run.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_support.hpp"

namespace {

using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string sample_xml() { return (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string(); }
std::string findings() { return (esi::test::source_dir() / "tests" / "cli" / "data" / "findings.xml").string(); }

// A device whose DC AssignActivate 0x0200 activates no SYNC signal (dc-assign-activate).
const char* yaml_with_finding = R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - type: D
    name: Device
    product_code: 1
    revision: 2
    mailbox: { size: 128, coe: true }
    dc:
      - { name: DC, assign_activate: 0x0200 }
)";

const char* eni = R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- exported by a configuration tool -->
<EtherCATConfig Version="1.3"><Config/></EtherCATConfig>
)";

TEST(EsiLintInputs, AYamlSourceIsLintedWithPositionsInTheYaml) {
    TempDir dir;
    write_text(dir / "device.yaml", yaml_with_finding);
    const auto r = run({tool("esi-lint"), "--fail-on", "info", (dir / "device.yaml").string()});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("device.yaml:10:38: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("[dc-assign-activate]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("    10 |       - { name: DC, assign_activate: 0x0200 }"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("text before the root element"), std::string::npos) << r.out;
}

TEST(EsiLintInputs, TheSamplesYamlSourcesLintClean) {
    for (const char* name : {"digital-io-8.yaml", "servo-item-c-series.yaml"}) {
        const auto r = run({tool("esi-lint"), (esi::test::source_dir() / "samples" / name).string()});
        EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.out << r.err;
        EXPECT_NE(r.out.find("0 errors"), std::string::npos) << name << "\n" << r.out;
    }
}

TEST(EsiLintInputs, AYamlSourceOnStandardInputIsToldApartByContent) {
    const auto r = run({tool("esi-lint"), "--fail-on", "info", "-"}, yaml_with_finding);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("<stdin>:10:38: "), std::string::npos) << r.out;
}

TEST(EsiLintInputs, AYamlSourceWithAnErrorIsReportedAtItsLine) {
    TempDir dir;
    write_text(dir / "bad.yaml", "vendor: { id: 0x10, name: Example }\ndevices:\n  - type: D\n    nmae: x\n");
    const auto r = run({tool("esi-lint"), (dir / "bad.yaml").string()});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("bad.yaml:4:5: error: "), std::string::npos) << r.out;
}

TEST(EsiLintInputs, ADirectoryWalkTakesXmlOnly) {
    TempDir dir;
    write_text(dir / "device.yaml", yaml_with_finding);
    write_text(dir / "ci.yaml", "stages: [test]\n");
    write_text(dir / "d.xml", esi::test::read_text(sample_xml()));
    const auto r = run({tool("esi-lint"), "--fail-on", "info", dir.path().string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("in 1 file\n"), std::string::npos) << r.out;
}

TEST(EsiLintInputs, AnEniFoundByAWalkIsSkippedWithANote) {
    TempDir dir;
    write_text(dir / "network.xml", eni);
    write_text(dir / "d.xml", esi::test::read_text(sample_xml()));
    const auto r = run({tool("esi-lint"), dir.path().string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("network.xml: note: skipped: not an ESI file (an ENI"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("in 1 file (1 not ESI, skipped)"), std::string::npos) << r.out;

    const auto j = nlohmann::json::parse(run({tool("esi-lint"), "--format", "json", dir.path().string()}).out);
    ASSERT_EQ(j["skipped"].size(), 1u) << j.dump();
    EXPECT_EQ(j["summary"]["files"], 1);
    EXPECT_EQ(j["diagnostics"].size(), 0u);
}

TEST(EsiLintInputs, AnEniNamedOnTheCommandLineIsAClearError) {
    TempDir dir;
    write_text(dir / "network.xml", eni);
    const auto r = run({tool("esi-lint"), (dir / "network.xml").string()});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("network.xml:3:1: error: not an ESI file (an ENI"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("[xml-unknown-root]"), std::string::npos) << r.out;
}

TEST(EsiLintInputs, AnUnknownRootFromAWalkIsStillAnError) {
    // A misspelt root is a broken ESI file, not a file of another kind.
    TempDir dir;
    write_text(dir / "d.xml", "<EtherCatInfo/>\n");
    const auto r = run({tool("esi-lint"), dir.path().string()});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("[xml-unknown-root]"), std::string::npos) << r.out;
}

TEST(EsiLintInputs, TheCorpusEnisAndLcecConfigsAreSkippedOnAWalk) {
    ESI_REQUIRE_CORPUS();
    for (const char* folder : {"eni", "master-configs/lcec"}) {
        TempDir dir;
        std::size_t copied = 0;
        for (const auto& entry : std::filesystem::directory_iterator(esi::test::shared_dir() / "corpus" / folder))
            if (entry.path().extension() == ".xml") {
                std::filesystem::copy_file(entry.path(), dir / entry.path().filename().string());
                ++copied;
            }
        ASSERT_GT(copied, 0u) << folder;
        const auto r = run({tool("esi-lint"), "--format", "json", dir.path().string()});
        EXPECT_EQ(r.exit_code, 0) << folder << "\n" << r.out << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j["skipped"].size(), copied) << folder << "\n" << r.out;
        EXPECT_EQ(j["diagnostics"].size(), 0u) << folder << "\n" << r.out;
    }
}

TEST(EsiLintInputs, AConfigErrorStopsTheRun) {
    TempDir dir;
    write_text(dir / ".esi-lint.yaml", "rules:\n  xml-hex-prefx: off\n");
    write_text(dir / "f.xml", esi::test::read_text(findings()));
    const auto r = run({tool("esi-lint"), (dir / "f.xml").string()});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.out.find(".esi-lint.yaml:2:3: error: unknown rule 'xml-hex-prefx'"), std::string::npos) << r.out;
    // Nothing was linted under defaults: the file's finding is not there, nor counted.
    EXPECT_EQ(r.out.find("[xml-hex-prefix]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("no file linted: the configuration has errors"), std::string::npos) << r.out;

    const auto piped = run({tool("esi-lint"), "--config", (dir / ".esi-lint.yaml").string(), "-"}, esi::test::read_text(findings()));
    EXPECT_EQ(piped.exit_code, 2) << piped.out;
    EXPECT_EQ(piped.out.find("[xml-hex-prefix]"), std::string::npos) << piped.out;
}

}  // namespace
