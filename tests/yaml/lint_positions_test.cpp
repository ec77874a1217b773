// The lint rules run on the derived model, and their findings point into the YAML source: the
// front end gives every element (derived ones included) a YAML position.

#include <gtest/gtest.h>

#include "esi/lint/lint.hpp"
#include "yaml/yaml_test_support.hpp"

using namespace esi;

TEST(YamlLintPositions, RuleFindingsPointAtTheYamlLine) {
    const DeviceSource s = esi::test::load_yaml(R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - type: D
    name: Device
    product_code: 1
    revision: 2
    mailbox: { size: 128, coe: true }
    dc:
      - { name: DC, assign_activate: 0x0200 }
)");
    ASSERT_TRUE(s.document) << esi::test::describe(s.diagnostics);
    const Diagnostics found = run_rules(*s.document, EffectiveConfig{});
    bool seen = false;
    for (const auto& d : found)
        if (d.rule == "dc-assign-activate") {
            seen = true;
            EXPECT_EQ(d.pos.line, 10u);
            EXPECT_EQ(d.pos.column, 38u);  // the value 0x0200
            EXPECT_EQ(d.path, "device.yaml");
        }
    EXPECT_TRUE(seen) << esi::test::describe(found);
}

TEST(YamlLintPositions, DerivedSyncManagersPointAtTheMailbox) {
    const DeviceSource s = esi::test::load_yaml(R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - type: D
    name: Device
    product_code: 1
    revision: 2
    mailbox: { size: 128, coe: true }
)");
    ASSERT_TRUE(s.document);
    const Device& d = esi::test::only_device(s);
    EXPECT_EQ(d.sms[0].pos.line, 8u);
    EXPECT_EQ(d.sms[2].pos.line, 4u);  // process-data SMs belong to the device
    EXPECT_EQ(d.dictionary()->find_object(0x1018)->pos.line, 4u);
}
