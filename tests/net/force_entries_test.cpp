// force_entries (issue 24): an entry the ESI marks not mappable stays an error, with a note
// naming the override; listed under force_entries it is mapped, with a warning.

#include <gtest/gtest.h>

#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

// The Elmo drive's 0x60FE:00 (the count of the digital outputs record) is not mappable in its ESI;
// an EC-Engineer export maps it.
const std::string elmo = "slaves:\n  - name: Axis\n    product_code: 0x00030924\n    revision: 0x00010420\n    pdos: [0x1607, 0x1A07]\n"
                         "    pdo_entries: { 0x1607: [0x607A:0:32, 0x60FE:0x00:8] }\n";

TEST(ForceEntries, NotMappableIsAnErrorThatNamesTheOverride) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(elmo);
    EXPECT_FALSE(built.network);
    const std::string text = esi::test::diagnostics_text(built.diagnostics);
    EXPECT_NE(text.find("[net-entry-not-mappable]"), std::string::npos) << text;
    EXPECT_NE(text.find("force_entries: [0x60FE:00]"), std::string::npos) << text;
}

TEST(ForceEntries, AForcedEntryIsMappedWithAWarning) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(elmo + "    force_entries: [0x60FE:0x00]\n");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    EXPECT_NE(esi::test::diagnostics_text(built.diagnostics).find("warning: 0x60FE:00"), std::string::npos)
        << esi::test::diagnostics_text(built.diagnostics);
    const auto& entries = built.network->slaves[0].pdos[0].entries;
    ASSERT_EQ(entries.size(), 2u);
    EXPECT_EQ(entries[1].index, 0x60FEu);
}

TEST(ForceEntries, MalformedEntriesAreReadErrors) {
    const esi::net::NetworkFileResult r =
        esi::net::read_network_text("slaves:\n  - { device: X, force_entries: [0x60FE, 0x60FE:0, 0x60FE:0] }\n", "n.yaml");
    EXPECT_FALSE(r.spec);
    EXPECT_NE(esi::test::diagnostics_text(r.diagnostics).find("a forced entry is INDEX:SUBINDEX"), std::string::npos);
    EXPECT_NE(esi::test::diagnostics_text(r.diagnostics).find("[yaml-duplicate-key]"), std::string::npos);
}

}  // namespace
