// A Fixed PDO restated exactly as the ESI declares it is not a change (issue: an EL1002 with
// `0x1A00: [0x6000:0x01:1]`, its ESI entries, was refused as "Fixed … cannot be changed");
// a real change of a Fixed PDO stays an error.

#include <gtest/gtest.h>

#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

TEST(FixedPdo, RestatedExactlyIsAccepted) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built =
        esi::test::build_corpus_network("slaves:\n  - { name: DI, device: EL1002, revision: 0x00100000, pdo_entries: { 0x1A00: [0x6000:0x01:1] } }\n");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    EXPECT_EQ(esi::test::diagnostics_text(built.diagnostics).find("net-pdo-fixed"), std::string::npos);
    EXPECT_FALSE(built.network->slaves[0].pdos[0].entries_configured);
}

TEST(FixedPdo, ARealChangeIsStillAnError) {
    ESI_REQUIRE_CORPUS();
    for (const char* entries : {"[0x6000:0x02:1]", "[0x6000:0x01:1, 0x0:0:7]", "[]"}) {
        const esi::net::BuildResult built = esi::test::build_corpus_network(
            std::string("slaves:\n  - { name: DI, device: EL1002, revision: 0x00100000, pdo_entries: { 0x1A00: ") + entries + " } }\n");
        EXPECT_FALSE(built.network) << entries;
        EXPECT_NE(esi::test::diagnostics_text(built.diagnostics).find("[net-pdo-fixed]"), std::string::npos)
            << entries << esi::test::diagnostics_text(built.diagnostics);
    }
}

}  // namespace
