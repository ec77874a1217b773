// The JSON view the templates render from: every field a template relies on, decoded the way the
// entry's type reads it. The rich fixture covers each value kind and naming hazard once.

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "codegen_test_support.hpp"
#include "esi/codegen/model_view.hpp"
#include "esi/xml/reader.hpp"

namespace {

using nlohmann::json;
namespace tc = esi::test::codegen;

json view_of(const std::filesystem::path& path, const esi::codegen::ViewOptions& options = {}) {
    const auto read = esi::read_esi_file(path);
    EXPECT_TRUE(read.document.has_value());
    EXPECT_FALSE(read.diagnostics.has_errors());
    const auto view = esi::codegen::model_view_json(*read.document, options);
    EXPECT_FALSE(view.diagnostics.has_errors());
    return json::parse(view.json);
}

const json& object(const json& device, unsigned index) {
    for (const auto& o : device["objects"])
        if (o["index"] == index) return o;
    throw std::runtime_error("object not in view");
}

class RichView : public ::testing::Test {
protected:
    static void SetUpTestSuite() { view_ = new json(view_of(tc::rich_esi())); }
    static void TearDownTestSuite() { delete view_; }
    const json& device() const { return (*view_)["devices"][0]; }
    static json* view_;
};
json* RichView::view_ = nullptr;

TEST_F(RichView, RootCarriesVersionSourceFileNameAndVendor) {
    EXPECT_EQ((*view_)["view_version"], esi::codegen::model_view_version);
    EXPECT_EQ((*view_)["source_file"], "rich-device.xml");  // the name only: output does not depend on the checkout path
    EXPECT_EQ((*view_)["vendor"]["id_hex"], "0x00000E4A");
    EXPECT_EQ((*view_)["device_count"], 1);
}

TEST_F(RichView, IdentityAndNames) {
    EXPECT_EQ(device()["identity"]["product_code_hex"], "0x00004711");
    EXPECT_EQ(device()["identity"]["revision_no"], 2);
    EXPECT_EQ(device()["c_name"], "rich_1");
    EXPECT_EQ(device()["macro_prefix"], "RICH_1");
}

TEST_F(RichView, ObjectsAreSortedAndNumberedConsecutively) {
    const auto& objects = device()["objects"];
    ASSERT_EQ(objects.size(), 14u);
    std::size_t position = 0;
    unsigned previous = 0;
    for (const auto& o : objects) {
        EXPECT_GT(o["index"].get<unsigned>(), previous);
        previous = o["index"];
        EXPECT_EQ(o["first_entry"], position);
        for (const auto& e : o["entries"]) EXPECT_EQ(e["position"], position++);
    }
    EXPECT_EQ(device()["entry_count"], position);
}

TEST_F(RichView, RecordWithoutSubindexZeroGetsOneHoldingTheHighestSubindex) {
    const auto& gains = object(device(), 0x2000);
    EXPECT_EQ(gains["object_code"], "RECORD");
    ASSERT_EQ(gains["entries"].size(), 3u);
    const auto& count = gains["entries"][0];
    EXPECT_EQ(count["subindex"], 0);
    EXPECT_TRUE(count["synthesized"]);
    EXPECT_EQ(count["default"]["text"], "2");
    EXPECT_EQ(gains["max_subindex"], 2);
}

TEST_F(RichView, RealDefaultFromDefaultDataIsTheIeeeValue) {
    const auto& gain = object(device(), 0x2000)["entries"][1];
    EXPECT_EQ(gain["c_type"], "float");
    EXPECT_EQ(gain["default"]["kind"], "real");
    EXPECT_EQ(gain["default"]["real_literal"], "1.5");
    EXPECT_EQ(gain["default"]["bits_hex"], "0x3FC00000");
    const auto& lreal = object(device(), 0x2004)["entries"][0];
    EXPECT_EQ(lreal["c_type"], "double");
    EXPECT_EQ(lreal["default"]["real_literal"], "1.5");
    EXPECT_EQ(lreal["default"]["bits_hex"], "0x3FF8000000000000");
}

TEST_F(RichView, SignedDefaultDataIsSignExtended) {
    const auto& offset = object(device(), 0x2000)["entries"][2];
    EXPECT_EQ(offset["default"]["kind"], "signed_integer");
    EXPECT_EQ(offset["default"]["int_literal"], "-1");
    EXPECT_EQ(offset["default"]["bits_hex"], "0xFFFF");
    EXPECT_EQ(offset["min"]["int_literal"], "-100");
    EXPECT_EQ(offset["max"]["int_literal"], "100");
}

TEST_F(RichView, SixtyFourBitExtremesAreValidLiterals) {
    const auto& lint = object(device(), 0x2001)["entries"][0];
    EXPECT_EQ(lint["default"]["int_literal"], "-5");
    EXPECT_EQ(lint["min"]["int_literal"], "(-9223372036854775807LL - 1)");
    const auto& ulint = object(device(), 0x2002)["entries"][0];
    EXPECT_EQ(ulint["default"]["uint_literal"], "0xFFFFFFFFFFFFFFFFull");
    EXPECT_FALSE(ulint["default"]["fits_32_bits"]);
    // SOES holds defaults in 32 bits: a larger one is not silently truncated.
    EXPECT_EQ(ulint["soes"]["value"], "0");
    EXPECT_TRUE(ulint["soes"]["value_truncated"]);
}

TEST_F(RichView, StringsAndOctetStrings) {
    const auto& name = object(device(), 0x1008)["entries"][0];
    EXPECT_EQ(name["c_type"], "char");
    EXPECT_EQ(name["c_array_suffix"], "[6]");
    EXPECT_EQ(name["default"]["kind"], "string");
    EXPECT_EQ(name["default"]["string_literal"], "\"RICH-1\"");
    EXPECT_EQ(name["soes"]["data"], "\"RICH-1\"");  // read-only string: a constant, no storage
    const auto& serial = object(device(), 0x2003)["entries"][0];
    EXPECT_EQ(serial["default"]["kind"], "bytes");
    EXPECT_EQ(serial["default"]["text"], "00 FF 7F");
    EXPECT_EQ(serial["default"]["string_literal"], "\"\\000\\377\\177\"");
    EXPECT_EQ(serial["default"]["byte_count"], 3);
}

TEST_F(RichView, NamesAreSanitisedForCodeAndComments) {
    const auto& serial = object(device(), 0x2003);
    EXPECT_EQ(serial["name_literal"], "\"Serial \\\"quoted\\\" \\?\\?= */ name\"");
    EXPECT_EQ(serial["comment"].get<std::string>().find("*/"), std::string::npos);
    EXPECT_EQ(object(device(), 0x2001)["c_name"], "default_");
    EXPECT_EQ(object(device(), 0x2004)["c_name"], "uebertemperatur_grenze");
    EXPECT_EQ(object(device(), 0x3000)["c_name"], "n_3_phase_currents");
    EXPECT_EQ(object(device(), 0x2000)["c_name"], "gains");
    EXPECT_EQ(object(device(), 0x2005)["c_name"], "gains_2005");  // the second "Gains"
}

TEST_F(RichView, AccessWordFollowsRestrictionsAndFlags) {
    const auto& pre = object(device(), 0x2001)["entries"][0];
    EXPECT_EQ(pre["access"], "rw");
    EXPECT_EQ(pre["access_word_hex"], "0x000F");  // read in every state, write in PreOP only
    EXPECT_EQ(pre["soes"]["access"], "ATYPE_RWpre");
    const auto& restricted = object(device(), 0x2004)["entries"][0];
    EXPECT_EQ(restricted["access_word_hex"], "0x0125");  // read PreOP+OP, write OP, backup
    EXPECT_EQ(restricted["soes"]["access"], "ATYPE_Rpre | ATYPE_Rop | ATYPE_Wop | ATYPE_BACKUP");
    const auto& input = object(device(), 0x6000)["entries"][1];
    EXPECT_TRUE(input["tx_mappable"]);
    EXPECT_EQ(input["soes"]["access"], "ATYPE_RO | ATYPE_TXPDO");
    EXPECT_EQ(input["soes"]["data"], "&Obj.inputs.input_1");
}

TEST_F(RichView, ArrayObjectEntries) {
    const auto& arr = object(device(), 0x3000);
    EXPECT_EQ(arr["object_code"], "ARRAY");
    EXPECT_EQ(arr["max_subindex"], 3);
    EXPECT_EQ(arr["entries"][3]["default"]["text"], "30");
    EXPECT_EQ(arr["entries"][3]["c_type"], "uint16_t");
}

TEST_F(RichView, PdoEntriesCarryMappingValuesAndOffsets) {
    const auto& rx = device()["rx_pdos"][0];
    EXPECT_EQ(rx["index_hex"], "0x1600");
    EXPECT_EQ(rx["entries"][0]["mapping_value_hex"], "0x70000001");
    EXPECT_EQ(rx["entries"][2]["mapping_value_hex"], "0x70100010");
    EXPECT_EQ(rx["entries"][2]["bit_offset"], 8);
    EXPECT_TRUE(rx["entries"][1]["is_padding"]);
    EXPECT_EQ(rx["bit_size"], 24);
}

TEST_F(RichView, DefaultAssignmentIsThePdosWithAnSm) {
    const auto& assignments = device()["pdo_assignments"];
    ASSERT_EQ(assignments.size(), 2u);
    EXPECT_EQ(assignments[1]["object_index_hex"], "0x1C13");
    ASSERT_EQ(assignments[1]["pdos"].size(), 2u);  // 0x1A02 has no Sm: optional, not assigned
    EXPECT_EQ(assignments[1]["pdos"][1]["index_hex"], "0x1A01");
}

TEST_F(RichView, ProcessImageLaysEntriesEndToEnd) {
    const auto& tx = device()["process_image"]["tx"];
    EXPECT_TRUE(tx["present"]);
    EXPECT_EQ(tx["byte_size"], 10);
    const auto& m = tx["members"];
    ASSERT_EQ(m.size(), 7u);
    EXPECT_EQ(m[0]["c_name"], "input_1");
    EXPECT_EQ(m[0]["bit_width"], 1);
    EXPECT_EQ(m[2]["bit_width"], 3);
    // A UINT at bit 5 is not byte-aligned: it becomes a 16-bit field.
    EXPECT_EQ(m[3]["c_name"], "counter");
    EXPECT_TRUE(m[3]["is_bit_field"]);
    EXPECT_EQ(m[3]["bit_offset"], 5);
    EXPECT_TRUE(m[4]["is_padding"]);
    EXPECT_EQ(m[4]["c_name"], "reserved_0");
    EXPECT_EQ(m[5]["c_name"], "position");
    EXPECT_FALSE(m[5]["is_bit_field"]);
    EXPECT_EQ(m[5]["byte_offset"], 4);
    EXPECT_EQ(m[6]["c_name"], "counter_1a01");  // the same object again, from the second PDO
}

TEST_F(RichView, MailboxBootstrapAndSyncManagers) {
    const auto& mb = device()["mailbox"];
    EXPECT_TRUE(mb["protocols"]["coe"]);
    EXPECT_TRUE(mb["protocols"]["foe"]);
    EXPECT_EQ(mb["protocol_bits_hex"], "0x000C");
    EXPECT_EQ(mb["out"]["start_address_hex"], "0x1000");
    EXPECT_EQ(mb["in"]["default_size"], 128);
    EXPECT_TRUE(mb["bootstrap"]["present"]);
    EXPECT_EQ(mb["bootstrap"]["out_size"], 256);
    EXPECT_EQ(mb["bootstrap"]["in_start_address_hex"], "0x1100");
    EXPECT_EQ(mb["init_cmds"][0]["transitions_text"], "PS");
    EXPECT_EQ(mb["init_cmds"][0]["data"][0]["hex"], "0x0A");
    EXPECT_EQ(device()["sm_outputs"]["number"], 2);
    EXPECT_TRUE(device()["sm_outputs"]["watchdog_trigger"]);
    EXPECT_EQ(device()["sync_managers"][3]["role_code"], 4);
}

TEST(ModelView, IsDeterministic) {
    const auto read = esi::read_esi_file(tc::rich_esi());
    ASSERT_TRUE(read.document);
    EXPECT_EQ(esi::codegen::model_view_json(*read.document).json, esi::codegen::model_view_json(*read.document).json);
}

TEST(ModelView, DuplicateObjectIsReportedAndTheFirstKept) {
    const char* xml = R"(<EtherCATInfo><Vendor><Id>1</Id><Name>V</Name></Vendor><Descriptions><Devices><Device>
<Type ProductCode="1" RevisionNo="1">D</Type><Name>D</Name><Profile><Dictionary><Objects>
<Object><Index>#x6000</Index><Name>First</Name><Type>UINT</Type><BitSize>16</BitSize></Object>
<Object><Index>#x6000</Index><Name>Second</Name><Type>UDINT</Type><BitSize>32</BitSize></Object>
</Objects></Dictionary></Profile></Device></Devices></Descriptions></EtherCATInfo>)";
    const auto read = esi::read_esi(xml, "dup.xml");
    ASSERT_TRUE(read.document);
    const auto view = esi::codegen::model_view_json(*read.document);
    ASSERT_EQ(view.diagnostics.size(), 1u);
    EXPECT_EQ(view.diagnostics.items()[0].rule, "codegen-duplicate-object");
    EXPECT_EQ(view.diagnostics.items()[0].pos.line, 4u);
    const json j = json::parse(view.json);
    ASSERT_EQ(j["devices"][0]["objects"].size(), 1u);
    EXPECT_EQ(j["devices"][0]["objects"][0]["name"], "First");
}

TEST(ModelView, DeviceSelectionAndNoMatch) {
    const auto read = esi::read_esi_file(tc::rich_esi());
    ASSERT_TRUE(read.document);
    esi::codegen::ViewOptions options;
    options.device = esi::DeviceSelector{0x4711, 2};
    EXPECT_EQ(json::parse(esi::codegen::model_view_json(*read.document, options).json)["device_count"], 1);
    options.device = esi::DeviceSelector{0x4711, 3};
    const auto none = esi::codegen::model_view_json(*read.document, options);
    ASSERT_TRUE(none.diagnostics.has_errors());
    EXPECT_EQ(none.diagnostics.items()[0].rule, "codegen-no-device");
}

TEST(ModelView, SymbolPrefixOverridesTheDeviceName) {
    const auto read = esi::read_esi_file(tc::rich_esi());
    ASSERT_TRUE(read.document);
    esi::codegen::ViewOptions options;
    options.symbol_prefix = "My Board";
    const json j = json::parse(esi::codegen::model_view_json(*read.document, options).json);
    EXPECT_EQ(j["devices"][0]["symbol_prefix"], "my_board");
    EXPECT_EQ(j["devices"][0]["macro_prefix"], "MY_BOARD");
    EXPECT_EQ(j["devices"][0]["c_name"], "rich_1");
}

// The documented view of the README sample, as a snapshot. After an intended change, regenerate
// with ESI_UPDATE_GOLDEN=1 and review the diff.
TEST(ModelView, GoldenViewOfTheSample) {
    const auto read = esi::read_esi_file(tc::sample_esi());
    ASSERT_TRUE(read.document);
    const std::string actual = esi::codegen::model_view_json(*read.document).json;
    const auto golden = tc::data_dir() / "example-digital-io.view.json";
    if (esi::test::rewrite_golden(golden, actual)) GTEST_SKIP() << "golden file " << golden << " rewritten";
    EXPECT_EQ(actual, esi::test::read_text(golden)) << "the view changed; if intended, rerun with ESI_UPDATE_GOLDEN=1";
}

}  // namespace
