// The YAML format additions the importer needs (docs/yaml-import.md, "Format changes"): each is
// checked on a small source, so that the parser keeps accepting what esi-gen --import writes.

#include <gtest/gtest.h>

#include "esi/yaml/source.hpp"

namespace {

const char* head = R"yaml(vendor: { id: 0x0E4A, name: V }
groups: [{ type: IO, name: IO }]
devices:
  - type: X1
    product_code: 0x10
    revision: 1
)yaml";

esi::DeviceSource load(const std::string& device_tail) { return esi::load_device_source(std::string(head) + device_tail, "t.yaml"); }

std::string errors(const esi::DeviceSource& s) {
    std::string out;
    for (const auto& d : s.diagnostics) out += std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.rule + " " + d.message + "\n";
    return out;
}

bool has_warning(const esi::DeviceSource& s, const std::string& text) {
    for (const auto& d : s.diagnostics)
        if (d.severity == esi::Severity::warning && d.message.find(text) != std::string::npos) return true;
    return false;
}

const esi::Device& device(const esi::DeviceSource& s) { return s.document->infos.at(0).devices.at(0); }

TEST(ImportFormat, InfoSubItemsAreKeptVerbatimInOrder) {
    const auto s = load(R"yaml(    name: X
    derive: false
    data_types:
      - { name: DT2000, bit_size: 48, sub_items: [{ subindex: 0, name: Count, type: USINT, bit_offset: 0 }, { subindex: 1, name: A, type: UDINT, bit_offset: 16 }] }
    objects:
      0x2000:
        name: R
        type: DT2000
        bit_size: 48
        info_sub_items:
          - { name: Count, default: 1 }
          - { name: A, default_data: "78563412", xml: { elements: ["<Note>n</Note>"] } }
)yaml");
    ASSERT_TRUE(s.document) << errors(s);
    const esi::Object* o = device(s).dictionary()->find_object(0x2000);
    ASSERT_NE(o, nullptr);
    ASSERT_TRUE(o->info);
    ASSERT_EQ(o->info->sub_items.size(), 2u);
    EXPECT_EQ(o->info->sub_items[0].name, "Count");
    EXPECT_EQ(o->info->sub_items[0].info.default_value->as_uint64(), 1u);
    EXPECT_EQ(o->info->sub_items[1].info.default_data->text, "78563412");
    ASSERT_EQ(o->info->sub_items[1].extras.elements.size(), 1u);
    EXPECT_EQ(o->info->sub_items[1].extras.elements[0].name, "Note");
    EXPECT_EQ(o->bit_size, 48u);
}

TEST(ImportFormat, InfoSubItemsAndEntriesAreOneHome) {
    const auto s = load(R"yaml(    name: X
    objects:
      0x2000:
        name: R
        entries: { 1: { name: A, type: UINT } }
        info_sub_items: [{ name: A, default: 1 }]
)yaml");
    EXPECT_FALSE(s.document);
    EXPECT_NE(errors(s).find("yaml-conflict"), std::string::npos) << errors(s);
}

TEST(ImportFormat, ZeroBitSizeNullNamesNullGroupAndLcIdZero) {
    const auto s = load(R"yaml(    name: { 0: neutral, en: English }
    comment: null
    group: null
    derive: false
    data_types:
      - { name: DT2000, bit_size: 16, sub_items: [{ subindex: 0, name: S, type: "STRING(0)", bit_size: 0, bit_offset: 0 }] }
    objects:
      0x2001: { name: Empty, type: "STRING(0)", bit_size: 0 }
)yaml");
    ASSERT_TRUE(s.document) << errors(s);
    const esi::Device& d = device(s);
    EXPECT_FALSE(d.group_type);
    EXPECT_TRUE(d.comments.empty());
    ASSERT_EQ(d.names.size(), 2u);
    EXPECT_EQ(d.names[0].lcid, 0u);
    EXPECT_EQ(d.dictionary()->find_object(0x2001)->bit_size, 0u);
    EXPECT_EQ(d.dictionary()->find_data_type("DT2000")->sub_items.at(0).bit_size, 0u);
    // Without `group` and with one group declared the device still joins it.
    const auto joined = load("    name: X\n");
    ASSERT_TRUE(joined.document) << errors(joined);
    EXPECT_EQ(device(joined).group_type, "IO");
}

TEST(ImportFormat, VendorSmFmmuAndPhysicsTextsAreKeptWithAWarning) {
    const auto s = load(R"yaml(    name: X
    physics: BB
    derive: false
    sms: [{ type: DynamicOutputs, address: 0x1000, size: 0 }, { type: OrbitaIn, address: 0x1100 }]
    fmmus: [OrbitaIn]
)yaml");
    ASSERT_TRUE(s.document) << errors(s);
    EXPECT_EQ(device(s).physics, "BB");
    EXPECT_EQ(device(s).sms.at(1).type, "OrbitaIn");
    EXPECT_EQ(device(s).fmmus.at(0).type, "OrbitaIn");
    EXPECT_TRUE(has_warning(s, "'physics'"));
    EXPECT_TRUE(has_warning(s, "SM type 'OrbitaIn'"));
    EXPECT_TRUE(has_warning(s, "FMMU type 'OrbitaIn'"));
}

TEST(ImportFormat, NoDictionaryIsAddedWhenObjectDerivationIsOff) {
    const auto off = load("    name: X\n    mailbox: { size: 128, coe: {} }\n    derive: false\n");
    ASSERT_TRUE(off.document) << errors(off);
    EXPECT_EQ(device(off).dictionary(), nullptr);
    const auto on = load("    name: X\n    mailbox: { size: 128, coe: {} }\n");
    ASSERT_TRUE(on.document) << errors(on);
    ASSERT_NE(device(on).dictionary(), nullptr);
    EXPECT_NE(device(on).dictionary()->find_object(0x1018), nullptr);
}

}  // namespace
