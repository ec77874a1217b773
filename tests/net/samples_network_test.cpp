// samples/networks/line.yaml: a line of the project's own sample devices (coupler with modules,
// digital I/O, CiA 402 servo with DC, encoder). It builds from the YAML device sources it names,
// and the ESI files esi-gen writes from those sources build exactly the same outputs.

#include <gtest/gtest.h>

#include "esi/io/atomic_write.hpp"
#include "esi/net/network.hpp"
#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

fs::path line_network() { return esi::test::source_dir() / "samples" / "networks" / "line.yaml"; }

std::vector<esi::OutputFile> outputs_of(const esi::net::NetworkSpec& spec) {
    const esi::net::BuildResult built = esi::net::build_network(spec, esi::net::BuildOptions{});
    EXPECT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    if (!built.network) return {};
    EXPECT_FALSE(built.diagnostics.has_errors());
    return esi::net::network_outputs(*built.network, esi::net::all_output_kinds(), "out");
}

TEST(SamplesNetwork, BuildsFromTheSourcesAndFromTheEsiFilesEsiGenWrites) {
    const esi::net::NetworkFileResult read = esi::net::read_network_file(line_network().string());
    ASSERT_TRUE(read.spec) << esi::test::diagnostics_text(read.diagnostics);
    const std::vector<esi::OutputFile> from_sources = outputs_of(*read.spec);
    ASSERT_EQ(from_sources.size(), 7u);

    esi::test::TempDir dir;
    esi::net::NetworkSpec from_esi = *read.spec;
    from_esi.esi.clear();
    for (const std::string& source : read.spec->esi) {
        const fs::path yaml = line_network().parent_path() / source;
        const auto gen = esi::test::run({esi::test::tool("esi-gen").string(), yaml.string(), "-o", (dir / "esi").string(), "--only", "esi"});
        ASSERT_EQ(gen.exit_code, 0) << gen.err;
    }
    from_esi.esi.push_back((dir / "esi").string());
    from_esi.path = (dir / "line.yaml").string();
    const std::vector<esi::OutputFile> from_files = outputs_of(from_esi);
    ASSERT_EQ(from_files.size(), from_sources.size());
    for (std::size_t i = 0; i < from_files.size(); ++i) {
        EXPECT_EQ(from_files[i].path, from_sources[i].path);
        EXPECT_EQ(from_files[i].content, from_sources[i].content) << from_files[i].path;
    }
}

TEST(SamplesNetwork, TheCliWritesEveryOutputAndTheMapAgreesWithTheEni) {
    esi::test::TempDir dir;
    const auto result = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "build", line_network().string(), "-o", dir.path().string()});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    for (const char* name : {"network.xml", "igh_config.h", "igh_config.c", "lcec.xml", "process_image.json", "process_image.csv", "process_image.md",
                             "process_image.html"})
        EXPECT_TRUE(fs::exists(dir / name)) << name;
    const std::string csv = esi::test::read_text(dir / "process_image.csv");
    EXPECT_NE(csv.find("Axis 1.Outputs.Target position,Axis 1,2,output,0x1601,0x607A,0x00,DINT,32,9,0\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("Coupler.Module 3 (EX-M-AI2).AI Inputs.Value 1,Coupler,0,input,0x1A02,0x6020,0x01,INT,16,1,0"), std::string::npos) << csv;
    const std::string eni = esi::test::read_text(dir / "network.xml");
    EXPECT_NE(eni.find("<Name>Axis 1.Outputs.Target position</Name>"), std::string::npos);
    EXPECT_NE(eni.find("<BitOffs>72</BitOffs>"), std::string::npos);

    // --only writes the kinds asked for and nothing else.
    esi::test::TempDir only;
    const auto lcec = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "build", line_network().string(), "-o",
                                      only.path().string(), "--only", "lcec,map"});
    ASSERT_EQ(lcec.exit_code, 0) << lcec.err;
    EXPECT_TRUE(fs::exists(only / "lcec.xml"));
    EXPECT_TRUE(fs::exists(only / "process_image.md"));
    EXPECT_FALSE(fs::exists(only / "network.xml"));
    EXPECT_FALSE(fs::exists(only / "igh_config.c"));
    EXPECT_FALSE(fs::exists(only / "process_image.html"));
}

TEST(SamplesNetwork, OutputsAreByteIdenticalRunToRun) {
    const esi::net::NetworkFileResult read = esi::net::read_network_file(line_network().string());
    ASSERT_TRUE(read.spec);
    const std::vector<esi::OutputFile> a = outputs_of(*read.spec);
    const std::vector<esi::OutputFile> b = outputs_of(*read.spec);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].content, b[i].content) << a[i].path;
}

}  // namespace
