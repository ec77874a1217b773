// igh_config.h/.c against the IgH master itself:
//  - they compile as C99 and as C++ with -Wall -Wextra -Werror against the declarations of IgH's
//    documented interface (data/igh_api/ecrt.h, written for the tests), for every corpus network;
//  - the tables agree with real `ethercat cstruct` output (../shared/corpus/master-configs/
//    igh-cstruct/) for the devices whose ESI is in the corpus: the EL1252 and EL2202 of
//    claudiolorini/led — entries, PDOs and SyncManagers (direction, PDO count, watchdog).

#include <gtest/gtest.h>

#include <sstream>

#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

bool have(const std::string& tool) { return esi::test::run({"/bin/sh", "-c", "command -v " + tool}).exit_code == 0; }

// The cstruct tables of one C text, per slave block in order: each table's rows reduced to
// their numbers ("0x6000, 0x01, 1"; a pointer "x + 3" becomes "+3", NULL stays NULL).
struct Tables {
    std::vector<std::string> entries, pdos, syncs;
};

std::string row_numbers(std::string row) {
    std::string out;
    std::istringstream fields(row);
    for (std::string f; std::getline(fields, f, ',');) {
        const std::size_t a = f.find_first_not_of(" \t{}");
        if (a == std::string::npos) continue;
        std::string t = f.substr(a, f.find_last_not_of(" \t{}") - a + 1);
        if (const std::size_t plus = t.find(" + "); plus != std::string::npos) t = "+" + t.substr(plus + 3);
        else if (t.find("_pdo") != std::string::npos) t = "+0";  // an array name alone points at its start
        out += (out.empty() ? "" : ", ") + t;
    }
    return out;
}

std::vector<Tables> read_tables(const std::string& c) {
    std::vector<Tables> out;
    std::istringstream in(c);
    std::vector<std::string>* table = nullptr;
    for (std::string line; std::getline(in, line);) {
        if (line.find("ec_pdo_entry_info_t ") != std::string::npos && line.find("[] = {") != std::string::npos) {
            out.emplace_back();
            table = &out.back().entries;
        } else if (line.find("ec_pdo_info_t ") != std::string::npos && line.find("[] = {") != std::string::npos && !out.empty()) {
            table = &out.back().pdos;
        } else if (line.find("ec_sync_info_t ") != std::string::npos && line.find("[] = {") != std::string::npos && !out.empty()) {
            table = &out.back().syncs;
        } else if (line.rfind("};", 0) == 0) {
            table = nullptr;
        } else if (table) {
            const std::size_t open = line.find('{');
            const std::size_t close = line.rfind('}');
            if (open == std::string::npos || close == std::string::npos) continue;
            const std::string row = row_numbers(line.substr(open + 1, close - open - 1));
            if (row.rfind("0xff", 0) == 0) continue;  // the terminator, written {0xff} or in full
            table->push_back(row);
        }
    }
    return out;
}

TEST(IghConfig, CompilesAsC99AndCxxAgainstTheDocumentedInterface) {
    ESI_REQUIRE_CORPUS();
    if (!have("gcc") || !have("g++")) GTEST_SKIP() << "no gcc/g++: compile check skipped";
    for (const esi::test::NamedNetwork& network : esi::test::corpus_networks()) {
        const esi::net::BuildResult built = esi::test::build_corpus_network(network.yaml);
        ASSERT_TRUE(built.network) << network.name << "\n" << esi::test::diagnostics_text(built.diagnostics);
        esi::test::TempDir dir;
        esi::test::write_text(dir / "igh_config.h", esi::net::write_igh_header(*built.network));
        esi::test::write_text(dir / "igh_config.c", esi::net::write_igh_source(*built.network));
        for (const std::vector<std::string>& command :
             {std::vector<std::string>{"gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-I" + esi::test::igh_api_dir().string(), "-c",
                                       (dir / "igh_config.c").string(), "-o", (dir / "c.o").string()},
              std::vector<std::string>{"g++", "-x", "c++", "-std=c++17", "-Wall", "-Wextra", "-Werror", "-I" + esi::test::igh_api_dir().string(), "-c",
                                       (dir / "igh_config.c").string(), "-o", (dir / "cxx.o").string()}}) {
            const auto result = esi::test::run(command);
            EXPECT_EQ(result.exit_code, 0) << network.name << ": " << command.front() << "\n" << result.err;
        }
    }
}

TEST(IghConfig, MatchesRealCstructOutputForCorpusDevices) {
    ESI_REQUIRE_CORPUS();
    // claudiolorini/led slaves.h: EL1252 rev 0x00120000, EL2202 rev 0x00100000, twice more each.
    const esi::net::BuildResult built = esi::test::build_corpus_network(R"(master: { name: led }
slaves:
  - { name: latches 1, product_code: 0x04E43052, revision: 0x00120000 }
  - { name: outputs 1, product_code: 0x089A3052, revision: 0x00100000 }
  - { name: outputs 2, product_code: 0x089A3052, revision: 0x00100000 }
  - { name: latches 2, product_code: 0x04E43052, revision: 0x00120000 }
  - { name: outputs 3, product_code: 0x089A3052, revision: 0x00100000 }
  - { name: latches 3, product_code: 0x04E43052, revision: 0x00120000 }
)");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    const std::vector<Tables> ours = read_tables(esi::net::write_igh_source(*built.network));
    const std::vector<Tables> theirs =
        read_tables(esi::test::read_text(esi::test::corpus_dir() / "master-configs" / "igh-cstruct" / "claudiolorini__led__slaves.h"));
    ASSERT_EQ(ours.size(), 6u);
    ASSERT_EQ(theirs.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(ours[i].entries, theirs[i].entries) << "slave " << i + 1 << " ec_pdo_entry_info_t";
        EXPECT_EQ(ours[i].pdos, theirs[i].pdos) << "slave " << i + 1 << " ec_pdo_info_t";
        EXPECT_EQ(ours[i].syncs, theirs[i].syncs) << "slave " << i + 1 << " ec_sync_info_t";
    }
}

TEST(IghConfig, RegistersEveryMappedEntryOnceWithBitPositionsWhereNeeded) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(
        "master: { name: led }\nslaves:\n  - { name: out, product_code: 0x089A3052, revision: 0x00100000 }\n");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    const std::string c = esi::net::write_igh_source(*built.network);
    // EL2202: four 1-bit entries, each registered with a bit position.
    EXPECT_NE(c.find("{0, 0, 0x00000002, 0x089a3052, 0x7000, 0x01, &out_channel_1_output, &out_channel_1_output_bit}"), std::string::npos) << c;
    EXPECT_NE(c.find("{0, 0, 0x00000002, 0x089a3052, 0x7010, 0x02, &out_channel_2_tristate, &out_channel_2_tristate_bit}"), std::string::npos) << c;
    EXPECT_NE(c.find("ecrt_slave_config_pdos(sc, EC_END, out_syncs)"), std::string::npos);
}

}  // namespace
