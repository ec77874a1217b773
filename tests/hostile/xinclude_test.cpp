// XInclude is not part of ESI (issue 16): an element of the XInclude namespace is an xml-xinclude
// error at its position; esi-lint reports it, and esi-gen and esi-gen --import refuse the file
// instead of copying the element into generated ESI or YAML. Nothing is ever included.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "esi/xml/reader.hpp"
#include "esi/yaml/source.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::run;
using esi::test::tool;

constexpr const char* anchor = "<Device Physics=\"YY\">";

std::string with_element(const std::string& element) {
    return esi::test::replace_once(esi::test::sample_esi(), anchor, std::string(anchor) + "\n        " + element);
}

std::vector<const esi::Diagnostic*> xinclude_errors(const esi::ReadResult& read) {
    std::vector<const esi::Diagnostic*> out;
    for (const auto& d : read.diagnostics)
        if (d.rule == "xml-xinclude") out.push_back(&d);
    return out;
}

TEST(XInclude, ElementsOfTheXIncludeNamespaceAreErrorsAtTheirPosition) {
    const std::vector<std::string> includes = {
        "<xi:include xmlns:xi=\"http://www.w3.org/2001/XInclude\" href=\"objects.xml\"/>",
        "<inc:include xmlns:inc=\"http://www.w3.org/2003/XInclude\" href=\"objects.xml\"/>",
        "<include xmlns=\"http://www.w3.org/2001/XInclude\" href=\"objects.xml\"/>",
        "<xi:include xmlns:xi=\"http://www.w3.org/2001/XInclude\" href=\"a.xml\"><xi:fallback/></xi:include>",
    };
    for (const auto& element : includes) {
        SCOPED_TRACE(element);
        const std::string text = with_element(element);
        const esi::ReadResult read = esi::read_esi(text, "device.xml");
        ASSERT_TRUE(read.document.has_value());
        const auto errors = xinclude_errors(read);
        ASSERT_FALSE(errors.empty());
        EXPECT_EQ(errors[0]->severity, esi::Severity::error);
        EXPECT_EQ(errors[0]->pos.line, esi::test::line_of(text, anchor) + 1);
        EXPECT_EQ(errors[0]->pos.column, 9u);
        EXPECT_NE(errors[0]->message.find("XInclude is not part of ESI"), std::string::npos) << errors[0]->message;
    }
}

// The namespace declared on the root or on an ancestor (the reader watches declarations as the
// parser reads them, and every start tag after the first).
TEST(XInclude, ADeclarationOnTheRootOrAnAncestorCoversTheElementsBelow) {
    const std::string sample = esi::test::sample_esi();
    const auto root_at = sample.find("<EtherCATInfo");
    ASSERT_NE(root_at, std::string::npos);
    std::string on_root = sample;
    on_root.insert(root_at + std::string("<EtherCATInfo").size(), " xmlns:xi=\"http://www.w3.org/2001/XInclude\"");
    on_root = esi::test::replace_once(on_root, anchor, std::string(anchor) + "\n        <xi:include href=\"a.xml\"/>");
    const esi::ReadResult from_root = esi::read_esi(on_root, "device.xml");
    ASSERT_EQ(xinclude_errors(from_root).size(), 1u);
    EXPECT_EQ(xinclude_errors(from_root)[0]->pos.line, esi::test::line_of(on_root, anchor) + 1);

    const std::string on_ancestor = esi::test::replace_once(
        sample, anchor, "<Device Physics=\"YY\" xmlns:x=\"http://www.w3.org/2003/XInclude\">\n        <Info><x:include/></Info>");
    EXPECT_EQ(xinclude_errors(esi::read_esi(on_ancestor, "device.xml")).size(), 1u);

    // An element before the declaration, or beside the element that declares it, is not in it.
    const std::string before = with_element("<xi:include/><Info xmlns:xi=\"http://www.w3.org/2001/XInclude\"/><xi:include/>");
    EXPECT_TRUE(xinclude_errors(esi::read_esi(before, "device.xml")).empty());
}

TEST(XInclude, OtherElementsNamedIncludeAreNotXInclude) {
    for (const std::string element : {"<my:include xmlns:my=\"urn:vendor\"/>", "<include href=\"x\"/>",
                                      "<xi:include xmlns:xi=\"urn:vendor-include\"/>", "<xi:include href=\"x\"/>"}) {
        SCOPED_TRACE(element);
        const esi::ReadResult read = esi::read_esi(with_element(element), "device.xml");
        ASSERT_TRUE(read.document.has_value());
        EXPECT_TRUE(xinclude_errors(read).empty());
    }
}

TEST(XInclude, ToolsReportOrRefuseAndWriteNothing) {
    esi::test::TempDir dir;
    const std::string text = with_element("<xi:include xmlns:xi=\"http://www.w3.org/2001/XInclude\" href=\"objects.xml\"/>");
    esi::test::write_text(dir / "device.xml", text);
    const std::string located = (dir / "device.xml").string() + ":" + std::to_string(esi::test::line_of(text, anchor) + 1) + ":9: error:";

    const auto lint = run({tool("esi-lint").string(), (dir / "device.xml").string()});
    EXPECT_EQ(lint.exit_code, 1);
    EXPECT_NE(lint.out.find(located), std::string::npos) << lint.out;
    EXPECT_NE(lint.out.find("[xml-xinclude]"), std::string::npos) << lint.out;

    const auto gen = run({tool("esi-gen").string(), (dir / "device.xml").string(), "-o", (dir / "out").string()});
    EXPECT_EQ(gen.exit_code, 2) << gen.err;
    EXPECT_NE(gen.err.find("[xml-xinclude]"), std::string::npos) << gen.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));

    const auto imported = run({tool("esi-gen").string(), "--import", (dir / "device.xml").string(), "-o", (dir / "device.yaml").string()});
    EXPECT_EQ(imported.exit_code, 2) << imported.err;
    EXPECT_NE(imported.err.find(located), std::string::npos) << imported.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "device.yaml"));
}

TEST(XInclude, AYamlXmlSnippetWithAnIncludeIsRefused) {
    esi::test::TempDir dir;
    const std::string source = "vendor: { id: 0x10, name: Example }\n"
                               "devices:\n"
                               "  - type: D\n"
                               "    name: Device\n"
                               "    product_code: 1\n"
                               "    revision: 2\n"
                               "    xml: { elements: [\"<xi:include xmlns:xi='http://www.w3.org/2001/XInclude' href='a.xml'/>\"] }\n";
    esi::test::write_text(dir / "device.yaml", source);
    const esi::DeviceSource loaded = esi::load_device_source_file(dir / "device.yaml");
    EXPECT_FALSE(loaded.document.has_value());
    bool refused = false;
    for (const auto& d : loaded.diagnostics)
        refused = refused || (d.rule == "yaml-xml" && d.pos.line == 7 && d.message.find("XInclude is not part of ESI") != std::string::npos);
    EXPECT_TRUE(refused);
}

}  // namespace
