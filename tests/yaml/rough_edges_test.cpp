// The YAML source's rough edges of issue 23: a passive terminal without identity, a minimal
// source without any group, and `pdo:` on a RECORD (applied to its sub-indices; the advice when a
// sub-index still is not mappable names the sub-index, not the object).

#include <gtest/gtest.h>

#include "esi/model/passive_terminal.hpp"
#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::describe;
using esi::test::load_yaml;
using esi::test::only_device;

TEST(YamlPassiveTerminal, DevicesWithoutIdentityAndWithoutEscAreAllowedAndNeverCollide) {
    const DeviceSource s = load_yaml(
        "vendor: { id: 2, name: Beckhoff }\n"
        "groups: [{ type: System, name: System }]\n"
        "devices:\n"
        "  - { type: EL9011, name: EL9011 End Terminal, physics: \"\" }\n"
        "  - { type: EL9100, name: EL9100 Power supply terminal, physics: \"\" }\n");
    ASSERT_TRUE(s.document) << describe(s.diagnostics);
    EXPECT_TRUE(s.diagnostics.empty()) << describe(s.diagnostics);
    const auto& devices = s.document->infos.at(0).devices;
    ASSERT_EQ(devices.size(), 2u);
    for (const Device& d : devices) {
        EXPECT_FALSE(d.type.product_code);
        EXPECT_FALSE(d.type.revision_no);
        EXPECT_TRUE(is_passive_terminal(d)) << d.type.text;
    }
}

TEST(YamlPassiveTerminal, ADeviceWithAnEscKeyStillNeedsItsIdentity) {
    const DeviceSource s = load_yaml(
        "vendor: { id: 2, name: V }\n"
        "devices:\n"
        "  - { type: EX, name: Ex, mailbox: { size: 128, coe: {} } }\n");
    EXPECT_FALSE(s.document);
    const std::string text = describe(s.diagnostics);
    EXPECT_NE(text.find("'product_code'"), std::string::npos) << text;
    EXPECT_NE(text.find("'revision'"), std::string::npos) << text;
}

TEST(YamlGroup, AMinimalSourceWithoutGroupsTakesTheDeviceTypeAsItsGroup) {
    const DeviceSource s = load_yaml(
        "vendor: { id: 0x0E4A, name: V }\n"
        "devices:\n"
        "  - { type: EX-1, name: Ex, product_code: 1, revision: 1, esc: et1100-spi }\n");
    ASSERT_TRUE(s.document) << describe(s.diagnostics);
    const Device& d = only_device(s);
    ASSERT_TRUE(d.group_type);
    EXPECT_EQ(*d.group_type, "EX-1");
    // The Group is derived, so the file is complete.
    const auto& groups = s.document->infos.at(0).groups;
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0].type, "EX-1");

    // With several groups declared the device must still say which.
    const DeviceSource t = load_yaml(
        "vendor: { id: 0x0E4A, name: V }\n"
        "groups: [{ type: A, name: A }, { type: B, name: B }]\n"
        "devices:\n"
        "  - { type: EX-1, name: Ex, product_code: 1, revision: 1 }\n");
    EXPECT_FALSE(t.document);
    EXPECT_NE(describe(t.diagnostics).find("a device needs 'group' when several groups are declared"), std::string::npos)
        << describe(t.diagnostics);
}

TEST(YamlRecordPdo, PdoOnARecordAppliesToItsSubIndices) {
    const DeviceSource s = load_yaml(
        "vendor: { id: 0x0E4A, name: V }\n"
        "devices:\n"
        "  - type: EX-1\n"
        "    name: Ex\n"
        "    product_code: 1\n"
        "    revision: 1\n"
        "    esc: et1100-spi\n"
        "    mailbox: { size: 128, coe: {} }\n"
        "    objects:\n"
        "      0x6000:\n"
        "        name: Inputs\n"
        "        pdo: tx\n"
        "        entries:\n"
        "          1: { name: A, type: UINT, access: ro }\n"
        "          2: { name: B, type: UINT, access: ro, pdo: none }\n"
        "    txpdo:\n"
        "      - { index: 0x1A00, name: In, entries: [\"0x6000:1\"] }\n");
    ASSERT_TRUE(s.document) << describe(s.diagnostics);
    const Pdo* p = only_device(s).find_pdo(0x1A00);
    ASSERT_NE(p, nullptr);
    ASSERT_EQ(p->entries.size(), 1u);
    EXPECT_EQ(p->entries[0].bit_len, 16u);
}

TEST(YamlRecordPdo, AnUnmappableSubIndexGetsAdviceForTheSubIndex) {
    const DeviceSource s = load_yaml(
        "vendor: { id: 0x0E4A, name: V }\n"
        "devices:\n"
        "  - type: EX-1\n"
        "    name: Ex\n"
        "    product_code: 1\n"
        "    revision: 1\n"
        "    mailbox: { size: 128, coe: {} }\n"
        "    objects:\n"
        "      0x6000:\n"
        "        name: Inputs\n"
        "        entries:\n"
        "          1: { name: A, type: UINT, access: ro }\n"
        "    txpdo:\n"
        "      - { index: 0x1A00, name: In, entries: [\"0x6000:1\"] }\n");
    EXPECT_FALSE(s.document);
    const std::string text = describe(s.diagnostics);
    EXPECT_NE(text.find("give sub-index 1 pdo: tx"), std::string::npos) << text;
    EXPECT_EQ(text.find("give the object pdo"), std::string::npos) << text;
}
