// --xsd messages (issue 22): schema findings carry the column of the element they name and are
// one line each (the GitHub and GitLab formats end a finding at a newline); an unusable schema
// says whether it is missing or does not compile.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_support.hpp"

namespace {

using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string findings() { return (esi::test::source_dir() / "tests" / "cli" / "data" / "findings.xml").string(); }

std::string schema_dir() { return (esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022").string(); }

// Schema errors on indented elements, one of them with a list of expected children.
const char* invalid = R"(<?xml version="1.0" encoding="UTF-8"?>
<EtherCATInfo>
  <Vendor>
      <Id>0xF3F</Id>
  </Vendor>
  <Descriptions>
    <Groups><Group><Type>G</Type><Name>g</Name></Group></Groups>
    <Devices><Device><Bogus/></Device></Devices>
  </Descriptions>
</EtherCATInfo>
)";

TEST(EsiLintXsd, SchemaFindingsCarryTheElementsColumn) {
    if (!esi::test::have_shared_corpus()) GTEST_SKIP() << "../shared/corpus not present: schema files missing";
    TempDir dir;
    write_text(dir / "d.xml", invalid);
    const auto r = run({tool("esi-lint"), "--xsd", schema_dir(), "--format", "json", (dir / "d.xml").string()});
    const auto j = nlohmann::json::parse(r.out);
    int schema = 0;
    for (const auto& d : j["diagnostics"]) {
        if (d["rule"] != "xml-schema") continue;
        ++schema;
        const std::string message = d["message"];
        if (message.starts_with("Element 'Id'")) {
            EXPECT_EQ(d["column"], 7) << d.dump();  // <Id> after six blanks
        } else if (message.starts_with("Element 'Bogus'")) {
            EXPECT_EQ(d["column"], 22) << d.dump();
        } else if (message.starts_with("Element 'Device'")) {
            EXPECT_EQ(d["column"], 14) << d.dump();  // the Device, not the Devices before it on the line
        }
    }
    EXPECT_GE(schema, 2) << r.out;
}

TEST(EsiLintXsd, NoMessageHasARawNewline) {
    if (!esi::test::have_shared_corpus()) GTEST_SKIP() << "../shared/corpus not present: schema files missing";
    TempDir dir;
    write_text(dir / "d.xml", invalid);
    for (const char* format : {"github", "text"}) {
        const auto r = run({tool("esi-lint"), "--xsd", schema_dir(), "--no-source", "--format", format, (dir / "d.xml").string()});
        std::size_t lines = 0;
        for (char c : r.out) lines += c == '\n';
        const auto j = nlohmann::json::parse(run({tool("esi-lint"), "--xsd", schema_dir(), "--format", "json", (dir / "d.xml").string()}).out);
        for (const auto& d : j["diagnostics"])
            EXPECT_EQ(d["message"].get<std::string>().find('\n'), std::string::npos) << d.dump();
        // One line per finding (plus the summary in text).
        EXPECT_EQ(lines, j["diagnostics"].size() + (std::string(format) == "text" ? 1 : 0)) << r.out;
    }
}

TEST(EsiLintXsd, AnUnusableSchemaSaysWhy) {
    TempDir dir;
    const auto missing = run({tool("esi-lint"), "--xsd", dir.path().string(), findings()});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.out.find("no usable EtherCATInfo.xsd in " + dir.path().string() + ": the file is missing"), std::string::npos)
        << missing.out;

    write_text(dir / "EtherCATInfo.xsd",
               "<xs:schema xmlns:xs=\"http://www.w3.org/2001/XMLSchema\"><xs:include schemaLocation=\"EtherCATBase.xsd\"/></xs:schema>\n");
    const auto broken = run({tool("esi-lint"), "--xsd", dir.path().string(), findings()});
    EXPECT_EQ(broken.exit_code, 2);
    EXPECT_NE(broken.out.find(": the file is there but does not compile"), std::string::npos) << broken.out;
}

}  // namespace
