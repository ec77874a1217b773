// Schema validation (`esi-lint --xsd DIR`) on hostile schemas and documents (issue 16): nothing is
// fetched over the network or read from outside DIR, libxml2's messages become diagnostics and
// never reach stderr, and a document that cannot be validated is an error, never a silent pass.

#include <unistd.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "esi/lint/xsd.hpp"
#include "esi/source_text.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::Listener;
using esi::test::run_child;

std::string lint_tool() { return esi::test::tool("esi-lint").string(); }

std::string schema_with(const std::string& references) {
    return "<?xml version=\"1.0\"?>\n<xs:schema xmlns:xs=\"http://www.w3.org/2001/XMLSchema\">\n" + references +
           "  <xs:element name=\"EtherCATInfo\"/>\n</xs:schema>\n";
}

std::vector<std::string> messages_of(const std::string& json_report) {
    std::vector<std::string> out;
    const nlohmann::json report = nlohmann::json::parse(json_report);
    for (const auto& d : report.at("diagnostics")) out.push_back(d.at("message").get<std::string>());
    return out;
}

bool any_contains(const std::vector<std::string>& messages, const std::string& part) {
    for (const auto& m : messages)
        if (m.find(part) != std::string::npos) return true;
    return false;
}

TEST(HostileXsd, ASchemaImportOverTheNetworkIsRefusedNotFetched) {
    Listener listener;
    const std::string url = "http://127.0.0.1:" + std::to_string(listener.port()) + "/imported.xsd";
    esi::test::TempDir dir;
    std::filesystem::create_directories(dir / "schemas");
    esi::test::write_text(dir / "schemas" / "EtherCATInfo.xsd",
                          schema_with("  <xs:import namespace=\"urn:remote\" schemaLocation=\"" + url + "\"/>\n"));
    esi::test::write_text(dir / "device.xml", esi::test::sample_esi());

    const auto lint = run_child({lint_tool(), "--xsd", (dir / "schemas").string(), "--format", "json", (dir / "device.xml").string()});
    EXPECT_FALSE(listener.anyone_connected()) << "the imported schema was fetched over the network";
    EXPECT_EQ(lint.exit_code, 2) << lint.out << lint.err;  // the schema set is unusable: a usage error
    EXPECT_EQ(lint.err, "") << "libxml2 wrote to stderr";
    const auto messages = messages_of(lint.out);
    EXPECT_TRUE(any_contains(messages, "refused to load '" + url + "'")) << lint.out;
    EXPECT_TRUE(any_contains(messages, "not validated against the schema")) << lint.out;
}

TEST(HostileXsd, SchemaFilesOutsideTheDirectoryAreRefusedEvenThroughALink) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "outside.xsd", "<?xml version=\"1.0\"?>\n<xs:schema xmlns:xs=\"http://www.w3.org/2001/XMLSchema\"/>\n");
    for (const char* include : {"../outside.xsd", "linked.xsd"}) {
        SCOPED_TRACE(include);
        const auto schemas = dir / (std::string("schemas-") + (include[0] == '.' ? "parent" : "link"));
        std::filesystem::create_directories(schemas);
        ASSERT_EQ(symlink((dir / "outside.xsd").c_str(), (schemas / "linked.xsd").c_str()), 0);
        esi::test::write_text(schemas / "EtherCATInfo.xsd", schema_with(std::string("  <xs:include schemaLocation=\"") + include + "\"/>\n"));
        esi::Diagnostics diagnostics;
        const auto set = esi::SchemaSet::load(schemas, diagnostics);
        std::vector<std::string> messages;
        for (const auto& d : diagnostics) messages.push_back(d.message);
        const std::string refused = std::string(include[0] == '.' ? "outside.xsd" : "linked.xsd") + "': schema validation reads only files inside";
        EXPECT_TRUE(any_contains(messages, refused)) << (messages.empty() ? "" : messages[0]);
        EXPECT_TRUE(diagnostics.has_errors());
    }
}

TEST(HostileXsd, IncludesInsideTheDirectoryStillLoad) {
    ESI_REQUIRE_CORPUS();
    // The ETG schemas include EtherCATBase.xsd from their own directory.
    esi::Diagnostics diagnostics;
    const auto set = esi::SchemaSet::load(esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022", diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << (diagnostics.empty() ? "" : diagnostics.items()[0].message);
    const esi::SourceText sample("sample.xml", esi::test::sample_esi());
    EXPECT_TRUE(set->validate(sample).empty());
}

TEST(HostileXsd, ADocumentThatCannotBeValidatedIsAnError) {
    ESI_REQUIRE_CORPUS();
    esi::Diagnostics load_diagnostics;
    const auto set = esi::SchemaSet::load(esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022", load_diagnostics);

    // Not readable by libxml2 (the reader refuses it too; the library call must not pass it).
    const esi::Diagnostics broken = set->validate(esi::SourceText("broken.xml", "<EtherCATInfo><Vendor></EtherCATInfo>"));
    ASSERT_EQ(broken.size(), 1u);
    EXPECT_EQ(broken.items()[0].rule, "xml-schema");
    EXPECT_EQ(broken.items()[0].severity, esi::Severity::error);
    EXPECT_NE(broken.items()[0].message.find("not validated against the schema: libxml2 cannot read the file"), std::string::npos)
        << broken.items()[0].message;

    // An entity reference: libxml2's validator cannot walk it and nothing expands it.
    std::string text = esi::test::sample_esi();
    text.insert(text.find("?>") + 2, "\n<!DOCTYPE EtherCATInfo [<!ENTITY name \"Example\">]>");
    text = esi::test::replace_once(text, "Example Automation GmbH", "&name;");
    const esi::Diagnostics entities = set->validate(esi::SourceText("entities.xml", text));
    ASSERT_EQ(entities.size(), 1u);
    EXPECT_NE(entities.items()[0].message.find("entity references, which are never expanded (the first: &name;)"), std::string::npos)
        << entities.items()[0].message;
    EXPECT_EQ(entities.items()[0].pos.line, esi::test::line_of(text, "&name;"));
    EXPECT_EQ(entities.items()[0].message.find("Internal error"), std::string::npos);

    // A root the ETG schemas do not describe.
    const esi::Diagnostics unknown = set->validate(esi::SourceText("other.xml", "<Other/>"));
    ASSERT_EQ(unknown.size(), 1u);
    EXPECT_NE(unknown.items()[0].message.find("describe no root element 'Other'"), std::string::npos) << unknown.items()[0].message;
}

TEST(HostileXsd, LibxmlMessagesNeverReachStderr) {
    ESI_REQUIRE_CORPUS();
    esi::test::TempDir dir;
    std::string text = esi::test::sample_esi();
    text.insert(text.find("?>") + 2, "\n<!DOCTYPE EtherCATInfo [<!ENTITY name \"Example\">]>");
    esi::test::write_text(dir / "entities.xml", esi::test::replace_once(text, "Example Automation GmbH", "&name;"));
    esi::test::write_text(dir / "invalid.xml", esi::test::replace_once(esi::test::sample_esi(), "<Vendor>", "<Vendor Unknown=\"1\">"));
    const auto schema = esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022";
    for (const char* format : {"text", "json", "sarif"}) {
        const auto lint = run_child({lint_tool(), "--xsd", schema.string(), "--format", format, (dir / "entities.xml").string(),
                                     (dir / "invalid.xml").string()});
        EXPECT_EQ(lint.exit_code, 1) << format << lint.err;
        EXPECT_EQ(lint.err, "") << format;
        EXPECT_NE(lint.out.find("not validated against the schema"), std::string::npos) << format;
        EXPECT_NE(lint.out.find("Unknown"), std::string::npos) << format;
    }
}

}  // namespace
