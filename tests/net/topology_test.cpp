// Physics of the line (issue 24, "What a network file must get right"): an E-Bus terminal right
// after an Ethernet-only device is an error naming the missing coupler; an Ethernet device after
// E-Bus terminals names the missing extension; a coupler with its terminals is fine.

#include <gtest/gtest.h>

#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

const char* drive = "{ name: Axis, product_code: 0x00030924, revision: 0x00010420 }";
const char* coupler = "{ name: Coupler, product_code: 0x044C2C52, revision: 0x00120000 }";
const char* terminal = "{ name: DI, device: EL1008 }";

std::string line(std::initializer_list<const char*> slaves) {
    std::string y = "slaves:\n";
    for (const char* s : slaves) y += std::string("  - ") + s + "\n";
    return y;
}

TEST(Topology, ACouplerCarriesItsTerminals) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(line({drive, coupler, terminal}));
    EXPECT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
}

TEST(Topology, ATerminalAfterADriveNamesTheMissingCoupler) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(line({drive, terminal}));
    EXPECT_FALSE(built.network);
    const std::string text = esi::test::diagnostics_text(built.diagnostics);
    EXPECT_NE(text.find("network.yaml:3:5: error: 'DI' (EL1008) is an E-Bus terminal"), std::string::npos) << text;
    EXPECT_NE(text.find("EtherCAT coupler (EK1100 or the like) is missing"), std::string::npos) << text;
}

TEST(Topology, ADriveAfterTerminalsNamesTheMissingExtension) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(line({coupler, terminal, drive}));
    EXPECT_FALSE(built.network);
    EXPECT_NE(esi::test::diagnostics_text(built.diagnostics).find("E-Bus extension (EK1110 or the like)"), std::string::npos)
        << esi::test::diagnostics_text(built.diagnostics);
}

}  // namespace
