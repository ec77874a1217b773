// The position-based requests over the protocol: hover, definition, references, completion and
// documentSymbol on the sample ESI file and a YAML source, as JSON (esi::navigate's own tests
// cover what they resolve; these cover the mapping and the index's life across versions).

#include <gtest/gtest.h>

#include <algorithm>

#include "lsp/lsp_client.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::LspClient;
using nlohmann::json;

const std::string sample_path = (esi::test::source_dir() / "samples/esi/example-digital-io.xml").string();

json at(const std::string& uri, int line, int character) {
    return json{{"textDocument", {{"uri", uri}}}, {"position", {{"line", line}, {"character", character}}}};
}

json range(int line, int start, int end) {
    return json{{"start", {{"line", line}, {"character", start}}}, {"end", {{"line", line}, {"character", end}}}};
}

class LspNavigation : public ::testing::Test {
protected:
    void SetUp() override {
        client.initialize();
        client.open(uri, esi::test::read_text(sample_path));
    }
    LspClient client;
    std::string uri = esi::test::file_uri(sample_path);
};

TEST_F(LspNavigation, CapabilitiesAnnounceTheFeatures) {
    LspClient other;
    const json caps = other.initialize().at("capabilities");
    EXPECT_TRUE(caps.at("hoverProvider").get<bool>());
    EXPECT_TRUE(caps.at("definitionProvider").get<bool>());
    EXPECT_TRUE(caps.at("referencesProvider").get<bool>());
    EXPECT_TRUE(caps.at("documentSymbolProvider").get<bool>());
    EXPECT_EQ(caps.at("completionProvider").at("triggerCharacters"), json::array({"<", "#"}));
}

TEST_F(LspNavigation, HoverOnAPdoEntry) {
    // Line 180: "            <Index>#x7000</Index>" in the RxPdo's entry.
    const json response = client.request("textDocument/hover", at(uri, 179, 21));
    const json& result = response.at("result");
    EXPECT_EQ(result.at("contents").at("kind"), "markdown");
    EXPECT_EQ(result.at("contents").at("value"),
              "**#x7000 Digital outputs**\n\n- type: `USINT`\n- size: 8 bits\n- access: rw\n- PDO mapping: R\n"
              "- default: `0`\n");
    EXPECT_EQ(result.at("range"), range(179, 19, 25));
    // Nothing there: null.
    EXPECT_TRUE(client.request("textDocument/hover", at(uri, 0, 0)).at("result").is_null());
}

TEST_F(LspNavigation, DefinitionAndReferences) {
    const json definition = client.request("textDocument/definition", at(uri, 179, 21)).at("result");
    EXPECT_EQ(definition, json::array({{{"uri", uri}, {"range", range(158, 23, 29)}}}));
    json params = at(uri, 158, 24);
    params["context"] = {{"includeDeclaration", true}};
    const json references = client.request("textDocument/references", params).at("result");
    // 0x1600's default mapping entry "#x70000008", the object, the RxPdo's entry.
    EXPECT_EQ(references, json::array({{{"uri", uri}, {"range", range(99, 67, 77)}},
                                       {{"uri", uri}, {"range", range(158, 23, 29)}},
                                       {{"uri", uri}, {"range", range(179, 19, 25)}}}));
    params["context"]["includeDeclaration"] = false;
    EXPECT_EQ(client.request("textDocument/references", params).at("result").size(), 2u);
}

TEST_F(LspNavigation, CompletionInAnEntryIndex) {
    const json result = client.request("textDocument/completion", at(uri, 179, 21)).at("result");
    EXPECT_FALSE(result.at("isIncomplete").get<bool>());
    const json& items = result.at("items");
    ASSERT_EQ(items.size(), 9u);
    EXPECT_EQ(items.back().at("label"), "#x7000");
    EXPECT_EQ(items.back().at("detail"), "Digital outputs");
    EXPECT_EQ(items.back().at("kind"), 6);
    EXPECT_EQ(items.back().at("textEdit"), (json{{"range", range(179, 19, 25)}, {"newText", "#x7000"}}));
}

TEST_F(LspNavigation, DocumentSymbolsNestDeviceOverItsParts) {
    const json symbols = client.request("textDocument/documentSymbol", {{"textDocument", {{"uri", uri}}}}).at("result");
    ASSERT_EQ(symbols.size(), 1u);
    EXPECT_EQ(symbols[0].at("name"), "EX-DIO-8");
    EXPECT_EQ(symbols[0].at("kind"), 5);
    const json& children = symbols[0].at("children");
    EXPECT_EQ(children[0].at("name"), "SM0");
    EXPECT_EQ(children[0].at("detail"), "MBoxOut");
    EXPECT_EQ(children[4].at("name"), "RxPdo #x1600");
    EXPECT_EQ(children[4].at("children")[0].at("name"), "#x7000:00");
}

TEST_F(LspNavigation, TheIndexFollowsTheDocumentsVersions) {
    // Rename the object's name in version 2: the hover shows the new text.
    client.notify("textDocument/didChange",
                  {{"textDocument", {{"uri", uri}, {"version", 2}}},
                   {"contentChanges", json::array({{{"range", range(159, 22, 37)}, {"text", "Renamed outputs"}}})}});
    const json result = client.request("textDocument/hover", at(uri, 179, 21)).at("result");
    EXPECT_EQ(result.at("contents").at("value").get<std::string>().substr(0, 26), "**#x7000 Renamed outputs**");
    // A closed document answers with nothing.
    client.notify("textDocument/didClose", {{"textDocument", {{"uri", uri}}}});
    EXPECT_TRUE(client.request("textDocument/hover", at(uri, 179, 21)).at("result").is_null());
    EXPECT_EQ(client.request("textDocument/definition", at(uri, 179, 21)).at("result"), json::array());
}

TEST_F(LspNavigation, BadParamsAndBadDocuments) {
    EXPECT_EQ(client.request("textDocument/hover", json::object()).at("error").at("code"), -32602);
    EXPECT_EQ(client.request("textDocument/hover", at(uri, -1, 0)).at("error").at("code"), -32602);
    // Past the end, an unknown document, a document that is not XML: empty answers.
    EXPECT_TRUE(client.request("textDocument/hover", at(uri, 100000, 5)).at("result").is_null());
    EXPECT_TRUE(client.request("textDocument/hover", at("file:///nowhere.xml", 1, 1)).at("result").is_null());
    client.open("file:///junk.xml", "<<<not xml at all");
    EXPECT_EQ(client.request("textDocument/documentSymbol", {{"textDocument", {{"uri", "file:///junk.xml"}}}}).at("result"),
              json::array());
    EXPECT_TRUE(client.request("textDocument/completion", at("file:///junk.xml", 0, 3)).at("result").at("items").empty());
}

TEST_F(LspNavigation, YamlSource) {
    const std::string path = (esi::test::source_dir() / "samples/digital-io-8.yaml").string();
    const std::string yaml_uri = esi::test::file_uri(path);
    const std::string text = esi::test::read_text(path);
    client.open(yaml_uri, text, 1, "yaml");
    const std::size_t offset = text.find("\"0x7000:2\"") + 3;
    const int line = static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
    const int character = static_cast<int>(offset - text.rfind('\n', offset) - 1);
    const json result = client.request("textDocument/hover", at(yaml_uri, line, character)).at("result");
    EXPECT_EQ(result.at("contents").at("value").get<std::string>().substr(0, 23), "**0x7000:2 Output 2**  ");
}

}  // namespace
