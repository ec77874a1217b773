#pragma once
// Helpers for the writer's unit tests: read a snippet, write it back, look at the output.

#include <gtest/gtest.h>

#include <string>

#include "esi/lint/xsd.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "support/test_support.hpp"
#include "writer/xml_tree_compare.hpp"

namespace esi::test {

// Reads XML that must parse; the test fails (and returns an empty document) otherwise.
inline EsiDocument read_ok(const std::string& xml) {
    auto result = read_esi(xml, "test.xml");
    EXPECT_TRUE(result.document.has_value()) << (result.diagnostics.empty() ? "" : result.diagnostics.items()[0].message);
    return result.document ? std::move(*result.document) : EsiDocument{};
}

inline std::string rewrite(const std::string& xml) { return write_esi(read_ok(xml)); }

// The tree differences between `xml` and its rewrite, one per line ("" when there are none).
inline std::string tree_differences(const std::string& xml) {
    const auto result = compare_xml_trees(xml, rewrite(xml));
    if (!result.parsed) return "not well-formed: " + result.error;
    std::string out;
    for (const auto& d : result.differences) out += std::string(to_string(d.kind)) + " " + d.path + " " + d.detail + "\n";
    return out;
}

// A device file around `device_body` (the children of <Device>), with vendor and group.
inline std::string device_file(const std::string& device_body, const std::string& device_attributes = R"( Physics="YY")") {
    return R"(<?xml version="1.0" encoding="UTF-8"?>
<EtherCATInfo Version="1.17">
  <Vendor><Id>#x00000E4A</Id><Name>Example</Name></Vendor>
  <Descriptions>
    <Groups><Group><Type>IO</Type><Name>I/O</Name></Group></Groups>
    <Devices>
      <Device)" +
           device_attributes + ">\n" + device_body + R"(
      </Device>
    </Devices>
  </Descriptions>
</EtherCATInfo>
)";
}

// Schema 1.17 from ../shared, loaded once; nullptr when the corpus is absent.
inline std::shared_ptr<SchemaSet> schema_1_17() {
    static const std::shared_ptr<SchemaSet> schemas = []() -> std::shared_ptr<SchemaSet> {
        if (!have_shared_corpus()) return nullptr;
        Diagnostics load;
        auto set = SchemaSet::load(shared_dir() / "corpus/schema/v1.17_siitool-2022", load);
        return load.empty() ? set : nullptr;
    }();
    return schemas;
}

// Schema errors of `xml` against 1.17, one per line ("" when valid).
inline std::string schema_errors(const std::string& xml) {
    std::string out;
    for (const auto& d : schema_1_17()->validate(SourceText("written.xml", xml)))
        out += "line " + std::to_string(d.pos.line) + ": " + d.message + "\n";
    return out;
}

inline bool contains(const std::string& haystack, const std::string& needle) { return haystack.find(needle) != std::string::npos; }

}  // namespace esi::test
