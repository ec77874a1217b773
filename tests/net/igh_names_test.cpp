// The C names of igh_config.h/.c (libesi/src/net/igh_names.hpp, docs/esi-net.md "IgH"):
//  - one scheme per entry name within a slave: a name that repeats is qualified by its PDO
//    everywhere (EL2202: `out_channel_1_output` … `out_channel_2_tristate`, no bare
//    `out_output` beside `out_channel_2_output`), a name that does not repeat is not;
//  - every variable of every corpus network is a valid C identifier without "__", unique,
//    and the same on a second run;
//  - slaves whose names become the same identifier are told apart by position.

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

// The offset variables a source defines ("unsigned int NAME;").
std::vector<std::string> variables(const std::string& c) {
    std::vector<std::string> out;
    std::istringstream in(c);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("unsigned int ", 0) == 0 && line.back() == ';') out.push_back(line.substr(13, line.size() - 14));
    return out;
}

std::vector<std::string> variables_of(const std::string& yaml) {
    const esi::net::BuildResult built = esi::test::build_corpus_network(yaml);
    EXPECT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    return built.network ? variables(esi::net::write_igh_source(*built.network)) : std::vector<std::string>{};
}

TEST(IghNames, ARepeatedEntryNameIsQualifiedByItsPdoEverywhere) {
    ESI_REQUIRE_CORPUS();
    // EL2202: PDOs "Channel 1" and "Channel 2", each with Output and TriState (1 bit each).
    const std::vector<std::string> vars = variables_of("slaves:\n  - { name: out, product_code: 0x089A3052, revision: 0x00100000 }\n");
    EXPECT_EQ(vars, (std::vector<std::string>{"out_channel_1_output", "out_channel_1_output_bit", "out_channel_1_tristate",
                                              "out_channel_1_tristate_bit", "out_channel_2_output", "out_channel_2_output_bit",
                                              "out_channel_2_tristate", "out_channel_2_tristate_bit"}));
}

TEST(IghNames, EveryChannelOfASixteenChannelTerminalFollowsTheSameScheme) {
    ESI_REQUIRE_CORPUS();
    const std::vector<std::string> vars = variables_of("slaves:\n  - { name: Inputs, device: EL1809 }\n");
    std::vector<std::string> offsets;
    for (const std::string& v : vars)
        if (v.size() < 4 || v.compare(v.size() - 4, 4, "_bit") != 0) offsets.push_back(v);
    ASSERT_EQ(offsets.size(), 16u);
    for (std::size_t i = 0; i < 16; ++i) EXPECT_EQ(offsets[i], "inputs_channel_" + std::to_string(i + 1) + "_input");
}

TEST(IghNames, AnEntryNameThatDoesNotRepeatIsNotQualified) {
    ESI_REQUIRE_CORPUS();
    // Elmo Gold: RxPDO 0x1601 "Outputs" (Target Velocity, Control word) and TxPDO 0x1A03
    // "Inputs": no entry name repeats.
    const std::vector<std::string> vars =
        variables_of("slaves:\n  - { name: Axis, product_code: 0x00030924, revision: 0x00010420, pdos: [0x1601, 0x1A03] }\n");
    ASSERT_FALSE(vars.empty());
    for (const std::string& v : vars) EXPECT_TRUE(v.rfind("axis_outputs", 0) != 0 && v.rfind("axis_inputs", 0) != 0) << v;
    EXPECT_NE(std::find(vars.begin(), vars.end(), "axis_control_word"), vars.end()) << ::testing::PrintToString(vars);
    EXPECT_NE(std::find(vars.begin(), vars.end(), "axis_status_word"), vars.end()) << ::testing::PrintToString(vars);
}

TEST(IghNames, SlavesNamedAlikeAreToldApartByPosition) {
    ESI_REQUIRE_CORPUS();
    const std::vector<std::string> vars = variables_of(
        "slaves:\n  - { name: Out-A, product_code: 0x089A3052, revision: 0x00100000 }\n  - { name: out a, product_code: 0x089A3052, revision: 0x00100000 }\n");
    EXPECT_NE(std::find(vars.begin(), vars.end(), "out_a_channel_1_output"), vars.end());
    EXPECT_NE(std::find(vars.begin(), vars.end(), "out_a_1_channel_1_output"), vars.end()) << ::testing::PrintToString(vars);
}

TEST(IghNames, EveryCorpusNetworksNamesAreUniqueValidAndStable) {
    ESI_REQUIRE_CORPUS();
    const std::regex c_identifier("[a-z_][a-z0-9_]*");
    for (const esi::test::NamedNetwork& n : esi::test::corpus_networks()) {
        const esi::net::BuildResult built = esi::test::build_corpus_network(n.yaml);
        ASSERT_TRUE(built.network) << n.name;
        const std::string c = esi::net::write_igh_source(*built.network);
        EXPECT_EQ(c, esi::net::write_igh_source(*built.network)) << n.name;
        const std::vector<std::string> vars = variables(c);
        EXPECT_FALSE(vars.empty()) << n.name;
        std::set<std::string> unique(vars.begin(), vars.end());
        EXPECT_EQ(unique.size(), vars.size()) << n.name;
        for (const std::string& v : vars) {
            EXPECT_TRUE(std::regex_match(v, c_identifier)) << n.name << ": " << v;
            EXPECT_EQ(v.find("__"), std::string::npos) << n.name << ": " << v;
        }
    }
}

}  // namespace
