// The SOES part of the view (docs/codegen.md, "SOES"): process-data limits for the largest
// assignment and mapping the dictionary allows, and PreOp-only writes of the PDO mapping and
// assignment objects. soes_stack_test.cpp runs the same tables in the real stack.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "codegen_test_support.hpp"
#include "esi/codegen/model_view.hpp"
#include "esi/yaml/source.hpp"

namespace {

using nlohmann::json;

json device_view_of(const std::string& sample) {
    const auto loaded = esi::load_device_source_file(esi::test::source_dir() / "samples" / sample);
    EXPECT_TRUE(loaded.document.has_value());
    if (!loaded.document) return {};
    const auto view = esi::codegen::model_view_json(*loaded.document, {});
    EXPECT_FALSE(view.diagnostics.has_errors());
    return json::parse(view.json)["devices"][0];
}

const json& entry(const json& device, unsigned index, unsigned subindex) {
    for (const auto& o : device["objects"])
        if (o["index"] == index)
            for (const auto& e : o["entries"])
                if (e["subindex"] == subindex) return e;
    throw std::runtime_error("entry not in view");
}

TEST(SoesView, WritableMappingsAreSizedForTheLargestMappingNotTheDefault) {
    // STÖBER: 0x1C12/0x1C13 hold four PDOs, each mapping object six entries, the longest mappable
    // object is 16 bits; the default maps 3 entries (5 bytes) out and 4 (7 bytes) in.
    const json d = device_view_of("inverter-stoeber-mds5000.yaml");
    for (const char* direction : {"rx", "tx"}) {
        SCOPED_TRACE(direction);
        EXPECT_EQ(d["soes"][direction]["remappable"], true);
        EXPECT_EQ(d["soes"][direction]["max_entry_bits"], 16);
        EXPECT_EQ(d["soes"][direction]["max_mappings"], 24);  // 4 PDOs x 6 entries
        EXPECT_EQ(d["soes"][direction]["max_bytes"], 48);     // 24 x 16 bits, whole 64-bit words
    }
}

TEST(SoesView, FixedMappingsAreTheAssignedPdosInWholeWords) {
    // TR encoder: one fixed TxPDO of 32 bits, no outputs at all.
    const json d = device_view_of("encoder-tr-linear.yaml");
    EXPECT_EQ(d["soes"]["tx"]["remappable"], false);
    EXPECT_EQ(d["soes"]["tx"]["max_mappings"], 1);
    EXPECT_EQ(d["soes"]["tx"]["max_bytes"], 8);
    // Without outputs SOES still gets a mapping slot and a buffer: with 0 it would expect the
    // application to define rxpdo.
    EXPECT_EQ(d["soes"]["rx"]["max_mappings"], 1);
    EXPECT_EQ(d["soes"]["rx"]["max_bytes"], 8);
}

TEST(SoesView, MappingAndAssignmentObjectsAreWritableInPreOpOnly) {
    const json d = device_view_of("inverter-stoeber-mds5000.yaml");
    for (const auto& [index, subindex] : std::vector<std::pair<unsigned, unsigned>>{{0x1600, 0}, {0x1600, 1}, {0x1A03, 6}, {0x1C12, 0}, {0x1C13, 2}}) {
        SCOPED_TRACE(index);
        const json& e = entry(d, index, subindex);
        EXPECT_EQ(e["soes"]["access"], "ATYPE_RWpre");
        EXPECT_EQ(e["access_word"], 0x3F);  // the ESI's own access is unchanged
    }
    // Application parameters keep the ESI's access.
    EXPECT_EQ(entry(d, 0x2102, 0)["soes"]["access"], "ATYPE_RW");
}

}  // namespace

namespace {

// STÖBER A261 (0x2105) keeps its error code in sub-index 0, a UDINT: the object list must not
// hold the entry count there (2 reads as "cycle time < 1 ms"). The UNSIGNED8 sub-index 0 of an
// ordinary record still answers its highest sub-index.
TEST(SoesView, ARecordsDataSubindexZeroGetsNoCountAsItsValue) {
    const json d = device_view_of("inverter-stoeber-mds5000.yaml");
    const json& error_code = entry(d, 0x2105, 0);
    EXPECT_EQ(error_code["data_type"], "UDINT");
    EXPECT_EQ(error_code["default"]["present"], false);
    EXPECT_EQ(error_code["soes"]["value"], "0");
    EXPECT_EQ(entry(d, 0x1600, 0)["soes"]["value"], "0x03");
}

}  // namespace
