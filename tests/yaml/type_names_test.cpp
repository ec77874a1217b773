// A misspelt data type in a YAML device source (issue 14, item 8) is named at the type with the
// name meant, instead of surfacing as advice about default_data or a missing size; the JSON
// Schema flags it in an editor too.

#include <gtest/gtest.h>

#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::describe;
using esi::test::load_yaml;

namespace {

const std::string header = R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - type: D
    name: Device
    product_code: 1
    revision: 2
    mailbox: { size: 128, coe: true }
    objects:
)";  // 9 lines; the next line is line 10

// The errors of `s` as "line:col message" lines.
std::string errors(const DeviceSource& s) {
    std::string out;
    for (const auto& d : s.diagnostics)
        if (d.severity == Severity::error) out += std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.message + "\n";
    return out;
}

}  // namespace

TEST(YamlTypeNames, AMisspeltTypeIsNamedWithTheTypeMeant) {
    const DeviceSource s = load_yaml(header + "      0x2000: { name: Setpoint, type: UNIT, access: rw, default: 0 }\n");
    EXPECT_FALSE(s.document);
    EXPECT_EQ(errors(s), "10:39 unknown type 'UNIT'; did you mean 'UINT'? (a basic type such as UINT, STRING(n), ARRAY [0..n] OF a "
                         "type, or a type declared in data_types)\n")
        << describe(s.diagnostics);
}

TEST(YamlTypeNames, NonStandardSpellingsAndRecordEntriesAndArrayElements) {
    const DeviceSource alias = load_yaml(header + "      0x2000: { name: Setpoint, type: UINT16, access: rw }\n");
    EXPECT_EQ(errors(alias).find("10:39 unknown type 'UINT16'; did you mean 'UINT'?"), 0u) << describe(alias.diagnostics);
    const DeviceSource entry = load_yaml(header + "      0x2001:\n        name: Gains\n        entries:\n          1: { name: Kp, type: RAEL }\n");
    EXPECT_EQ(errors(entry).find("13:32 unknown type 'RAEL'; did you mean 'REAL'?"), 0u) << describe(entry.diagnostics);
    EXPECT_EQ(entry.diagnostics.count(Severity::error), 1u) << "one error, no follow-up about the record: " << describe(entry.diagnostics);
    const DeviceSource array = load_yaml(header + "      0x2002: { name: Table, type: DITN, array: 4 }\n");
    EXPECT_NE(errors(array).find("unknown type 'DITN'; did you mean 'DINT'?"), std::string::npos) << describe(array.diagnostics);
}

TEST(YamlTypeNames, KnownAndDeclaredTypesAreAccepted) {
    const DeviceSource s = load_yaml(header + R"(      0x2000: { name: A, type: UINT, access: rw, default: 0 }
      0x2001: { name: B, type: STRING(8), access: ro }
      0x2002: { name: C, type: "ARRAY [0..3] OF BYTE", access: ro }
    data_types:
      - name: UINT1
        bit_size: 1
)");
    EXPECT_EQ(errors(s), "") << describe(s.diagnostics);
}

TEST(YamlTypeNames, ATypeDeclaredInTheSourceIsNotAMisspelling) {
    // UINT1 is close to UINT, but the source declares it (vendor files do).
    const DeviceSource s = load_yaml(header + R"(      0x2000: { name: A, type: UINT1, access: ro }
    data_types:
      - name: UINT1
        bit_size: 1
)");
    EXPECT_EQ(errors(s).find("unknown type"), std::string::npos) << describe(s.diagnostics);
}
