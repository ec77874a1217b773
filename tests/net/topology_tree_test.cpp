// Trees (issue 24 §4): `previous_slave`/`previous_port` hang a slave off a junction's or
// coupler's other port; the port must exist, carry the slave's physics and serve one slave; the
// list must be in the order the frame visits the slaves (an ESC's ports A, D, B, C); the ENI's
// PreviousPort names the port and the upstream station address.

#include <gtest/gtest.h>

#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

const char* coupler = "{ name: Coupler, product_code: 0x044C2C52, revision: 0x00120000 }";
const char* junction = "{ name: Junction, product_code: 0x04622C52, revision: 0x00110000 }";  // EK1122, ports KYKY

std::string network(std::initializer_list<std::string> slaves) {
    std::string y = "slaves:\n";
    for (const std::string& s : slaves) y += "  - " + s + "\n";
    return y;
}

std::string axis(const std::string& name, const std::string& extra) {
    return "{ name: " + name + ", product_code: 0x00030924, revision: 0x00010420" + extra + " }";
}

std::string errors_of(const std::string& yaml) {
    const esi::net::BuildResult built = esi::test::build_corpus_network(yaml);
    EXPECT_FALSE(built.network);
    return esi::test::diagnostics_text(built.diagnostics);
}

std::string previous_port(const std::string& eni, const std::string& slave) {
    const std::size_t at = eni.find("<Name><![CDATA[" + slave + "]]></Name>");
    if (at == std::string::npos) return "no slave " + slave;
    const std::size_t pp = eni.find("<PreviousPort", at), next = eni.find("<Slave>", at);
    if (pp == std::string::npos || (next != std::string::npos && pp > next)) return "none";
    const std::size_t port = eni.find("<Port>", pp), addr = eni.find("<PhysAddr>", pp);
    return eni.substr(port + 6, 1) + "@" + eni.substr(addr + 10, 4);
}

TEST(TopologyTree, AJunctionsBranchesGetTheirPortsInTheEni) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(network(
        {coupler, junction, axis("Axis D", ", previous_port: D"), axis("Axis B", ", previous_slave: Junction, previous_port: B"),
         "{ name: Outputs, device: EL2008, revision: 0x00120000, previous_slave: Junction }"}));
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    const std::string eni = esi::net::write_eni(*built.network);
    EXPECT_EQ(previous_port(eni, "Coupler"), "none");
    EXPECT_EQ(previous_port(eni, "Junction"), "B@1001");  // the coupler's E-Bus port
    EXPECT_EQ(previous_port(eni, "Axis D"), "D@1002");
    EXPECT_EQ(previous_port(eni, "Axis B"), "B@1002");
    EXPECT_EQ(previous_port(eni, "Outputs"), "C@1002");  // the junction's E-Bus port, the first free K port
    EXPECT_EQ(built.network->slaves[4].auto_inc_addr, 0xFFFCu);
}

TEST(TopologyTree, TheListMustFollowTheFramesPortOrder) {
    ESI_REQUIRE_CORPUS();
    // B listed before D: the frame reaches D's branch first.
    const std::string text = errors_of(network({coupler, junction, axis("Axis B", ", previous_port: B"),
                                                axis("Axis D", ", previous_slave: Junction, previous_port: D")}));
    EXPECT_NE(text.find("network.yaml:5:5: error: 'Axis D' is listed as slave 4, but the frame reaches it as slave 3, before 'Axis B'"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("A, D, B, C (0, 3, 1, 2)"), std::string::npos) << text;
}

TEST(TopologyTree, APortServesOneSlave) {
    ESI_REQUIRE_CORPUS();
    const std::string text = errors_of(network({coupler, junction, axis("Axis 1", ", previous_port: D"),
                                                axis("Axis 2", ", previous_slave: Junction, previous_port: D")}));
    EXPECT_NE(text.find("network.yaml:5:"), std::string::npos) << text;
    EXPECT_NE(text.find("port D of 'Junction' is taken by 'Axis 1' already"), std::string::npos) << text;
}

TEST(TopologyTree, ThePortMustExistAndCarryTheSlavesPhysics) {
    ESI_REQUIRE_CORPUS();
    std::string text = errors_of(network({coupler, "{ name: DI, device: EL1008 }", "{ name: DO, device: EL2008, previous_port: D }"}));
    EXPECT_NE(text.find("error: 'DI' (EL1008, ports 'KK') has no port D"), std::string::npos) << text;
    text = errors_of(network({coupler, junction, "{ name: DO, device: EL2008, previous_port: D }"}));
    EXPECT_NE(text.find("port D of 'Junction' (EK1122, ports 'KYKY') is Ethernet, but 'DO' (EL2008) connects by E-Bus"), std::string::npos)
        << text;
    text = errors_of(network({coupler, junction, axis("Axis", ", previous_port: A")}));
    EXPECT_NE(text.find("previous_port is B, C or D (A is the port towards the master), not 'A'"), std::string::npos) << text;
}

TEST(TopologyTree, PreviousSlaveIsLocatedWhenItNamesNothingOrALaterSlave) {
    ESI_REQUIRE_CORPUS();
    std::string text = errors_of(network({coupler, axis("Axis", ", previous_slave: Nowhere")}));
    EXPECT_NE(text.find("network.yaml:3:"), std::string::npos) << text;
    EXPECT_NE(text.find("previous_slave 'Nowhere' names no slave of the network"), std::string::npos) << text;
    text = errors_of(network({coupler, axis("Axis", ", previous_slave: Junction"), junction}));
    EXPECT_NE(text.find("hangs off 'Junction', which is listed after it"), std::string::npos) << text;
    text = errors_of(network({axis("Axis", ", previous_port: B"), coupler}));
    EXPECT_NE(text.find("'Axis' is the first slave: it hangs off the master"), std::string::npos) << text;
}

TEST(TopologyTree, ADefaultPortAlreadyTakenIsNamed) {
    ESI_REQUIRE_CORPUS();
    // The EK1100 has one E-Bus port (B): a second E-Bus branch off it cannot be wired.
    const std::string text = errors_of(network({coupler, "{ name: DI, device: EL1008 }", "{ name: DO, device: EL2008, previous_slave: Coupler }"}));
    EXPECT_NE(text.find("every port of 'Coupler' (EK1100, ports 'YKY') that 'DO' (EL2008) could use is taken (port B: 'DI')"),
              std::string::npos)
        << text;
}

}  // namespace
