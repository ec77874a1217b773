// Diagnostics and code actions through the server: the findings esi-lint gives, on open and after
// full and incremental changes (UTF-16 columns after non-ASCII text), fixes and suppressions that
// make their finding go away, documents that are not ESI files.

#include <gtest/gtest.h>

#include <set>

#include "esi/lint/lint.hpp"
#include "lsp/lsp_client.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::LspClient;
using nlohmann::json;

// A small ESI file with one fixable finding (0x for #x) on line 6 (0-based 5).
std::string sample_with_hex_prefix(const std::string& comment = "") {
    std::string text = esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml");
    const std::size_t at = text.find("<Id>#x");
    text.replace(at, 6, "<Id>" + comment + "0x");
    return text;
}

std::set<std::pair<std::string, int>> rules_and_lines(const json& diagnostics) {
    std::set<std::pair<std::string, int>> out;
    for (const json& d : diagnostics) out.emplace(d.value("code", ""), d.at("range").at("start").at("line").get<int>() + 1);
    return out;
}

// Applies LSP TextEdits (non-overlapping) to a text, as an editor does.
std::string apply(std::string text, json edits);

std::size_t offset_of(const std::string& text, const json& position) {
    std::size_t at = 0;
    for (int line = 0; line < position.at("line").get<int>(); ++line) at = text.find('\n', at) + 1;
    int units = position.at("character").get<int>();
    while (units > 0 && at < text.size() && text[at] != '\n') {
        const auto c = static_cast<unsigned char>(text[at]);
        const std::size_t n = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
        units -= n == 4 ? 2 : 1;
        at += n;
    }
    return at;
}

std::string apply(std::string text, json edits) {
    std::vector<std::tuple<std::size_t, std::size_t, std::string>> resolved;
    for (const json& e : edits)
        resolved.emplace_back(offset_of(text, e["range"]["start"]), offset_of(text, e["range"]["end"]), e["newText"].get<std::string>());
    std::sort(resolved.begin(), resolved.end(), [](const auto& a, const auto& b) { return std::get<0>(a) > std::get<0>(b); });
    for (const auto& [from, to, replacement] : resolved) text.replace(from, to - from, replacement);
    return text;
}

json code_actions(LspClient& client, const std::string& uri, const json& range) {
    return client.request("textDocument/codeAction",
                          {{"textDocument", {{"uri", uri}}}, {"range", range}, {"context", {{"diagnostics", json::array()}}}})
        .at("result");
}

TEST(LspDiagnostics, SameFindingsAsEsiLintOnCorpusFiles) {
    ESI_REQUIRE_CORPUS();
    LspClient client;
    client.initialize();
    for (const char* name : {"Beckhoff__EL3xxx__dls-ethercat.xml", "Beckhoff__EL66xx__dls-ethercat.xml"}) {
        const std::filesystem::path path = esi::test::corpus_esi_dir() / name;
        // The editor holds the text decoded; the server lints it as the file would be.
        const std::string bytes = esi::test::read_text(path);
        const esi::LintReport expected = esi::lint_paths({path}, {});
        std::set<std::pair<std::string, int>> want;
        for (const auto& d : expected.files.at(0).diagnostics) want.emplace(d.rule, static_cast<int>(d.pos.line));
        const std::string uri = esi::test::file_uri(path);
        client.open(uri, bytes);
        const std::optional<json> got = client.diagnostics_for(uri, std::chrono::seconds(60));
        ASSERT_TRUE(got) << name;
        EXPECT_EQ(rules_and_lines(got->at("diagnostics")), want) << name;
        for (const json& d : got->at("diagnostics")) {
            EXPECT_EQ(d.at("source"), "esi-lint");
            EXPECT_GE(d.at("severity").get<int>(), 1);
            EXPECT_LE(d.at("severity").get<int>(), 3);
        }
    }
}

TEST(LspDiagnostics, IncrementalChangesKeepUtf16Columns) {
    LspClient client;
    client.initialize();
    esi::test::TempDir dir;
    const std::string uri = esi::test::file_uri(dir / "device.xml");
    std::string text = esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml");
    client.open(uri, text);
    std::optional<json> published = client.diagnostics_for(uri);
    ASSERT_TRUE(published);
    EXPECT_TRUE(published->at("diagnostics").empty()) << published->dump();

    // Line 6 is "    <Id>#x00000E4A</Id>". Put a comment with 'ä' (1 unit, 2 bytes) and an emoji
    // (2 units, 4 bytes) before the value, then replace "#x" by "0x" by UTF-16 range.
    const std::string comment = "<!--\xC3\xA4\xF0\x9F\x98\x80-->";  // <!--ä😀-->
    client.notify("textDocument/didChange",
                  {{"textDocument", {{"uri", uri}, {"version", 2}}},
                   {"contentChanges", json::array({{{"range", {{"start", {{"line", 5}, {"character", 8}}}, {"end", {{"line", 5}, {"character", 8}}}}},
                                                    {"text", comment}}})}});
    // "    <Id>" (8) + "<!--" (4) + ä (1) + 😀 (2) + "-->" (3) = 18: the value starts at 18.
    client.notify("textDocument/didChange",
                  {{"textDocument", {{"uri", uri}, {"version", 3}}},
                   {"contentChanges", json::array({{{"range", {{"start", {{"line", 5}, {"character", 18}}}, {"end", {{"line", 5}, {"character", 20}}}}},
                                                    {"text", "0x"}}})}});
    do {
        published = client.diagnostics_for(uri);
        ASSERT_TRUE(published);
    } while (published->at("version") != 3);
    const json& diagnostics = published->at("diagnostics");
    ASSERT_EQ(diagnostics.size(), 1u) << diagnostics.dump();
    EXPECT_EQ(diagnostics[0].at("code"), "xml-hex-prefix");
    EXPECT_EQ(diagnostics[0].at("range").at("start"), json({{"line", 5}, {"character", 18}}));
    EXPECT_EQ(diagnostics[0].at("range").at("end"), json({{"line", 5}, {"character", 20}}));

    // The fix, applied as the editor would, gives back the text without the finding.
    const json actions = code_actions(client, uri, diagnostics[0].at("range"));
    const auto fix = std::find_if(actions.begin(), actions.end(), [](const json& a) { return a.value("isPreferred", false); });
    ASSERT_NE(fix, actions.end()) << actions.dump();
    EXPECT_EQ(fix->at("kind"), "quickfix");
    const std::string current = sample_with_hex_prefix(comment);
    const std::string fixed = apply(current, fix->at("edit").at("changes").at(uri));
    EXPECT_EQ(fixed, sample_with_hex_prefix(comment).replace(sample_with_hex_prefix(comment).find("0x00000E4A"), 2, "#x"));

    // A full-text change replaces everything.
    client.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 4}}},
                                             {"contentChanges", json::array({{{"text", fixed}}})}});
    do {
        published = client.diagnostics_for(uri);
        ASSERT_TRUE(published);
    } while (published->at("version") != 4);
    EXPECT_TRUE(published->at("diagnostics").empty()) << published->dump();
}

TEST(LspCodeActions, SuppressionCommentSilencesTheFinding) {
    LspClient client;
    client.initialize();
    esi::test::TempDir dir;
    const std::string uri = esi::test::file_uri(dir / "device.xml");
    const std::string text = sample_with_hex_prefix();
    client.open(uri, text);
    const std::optional<json> published = client.diagnostics_for(uri);
    ASSERT_TRUE(published);
    ASSERT_EQ(published->at("diagnostics").size(), 1u);
    const json actions = code_actions(client, uri, published->at("diagnostics")[0].at("range"));
    const auto suppress = std::find_if(actions.begin(), actions.end(),
                                       [](const json& a) { return a.at("title").get<std::string>().starts_with("Suppress"); });
    ASSERT_NE(suppress, actions.end()) << actions.dump();
    const std::string suppressed = apply(text, suppress->at("edit").at("changes").at(uri));
    EXPECT_NE(suppressed.find("<!-- esi-lint: disable-next-line=xml-hex-prefix -->"), std::string::npos);
    const esi::FileReport relinted = esi::lint_bytes(suppressed, "device.xml", esi::EffectiveConfig{});
    EXPECT_TRUE(relinted.diagnostics.empty()) << (relinted.diagnostics.empty() ? "" : relinted.diagnostics.items()[0].message);
}

TEST(LspCodeActions, NoActionsOutsideTheFindingOrForUnknownDocuments) {
    LspClient client;
    client.initialize();
    esi::test::TempDir dir;
    const std::string uri = esi::test::file_uri(dir / "device.xml");
    client.open(uri, sample_with_hex_prefix());
    ASSERT_TRUE(client.diagnostics_for(uri));
    const json far = {{"start", {{"line", 30}, {"character", 0}}}, {"end", {{"line", 30}, {"character", 1}}}};
    EXPECT_TRUE(code_actions(client, uri, far).empty());
    EXPECT_TRUE(code_actions(client, "file:///not/open.xml", far).empty());
}

TEST(LspDiagnostics, ConfigOfTheFilesDirectoryApplies) {
    LspClient client;
    client.initialize();
    esi::test::TempDir dir;
    esi::test::write_text(dir / ".esi-lint.yaml", "rules: { xml-hex-prefix: error }\n");
    const std::string uri = esi::test::file_uri(dir / "device.xml");
    client.open(uri, sample_with_hex_prefix());
    std::optional<json> published = client.diagnostics_for(uri);
    ASSERT_TRUE(published);
    ASSERT_EQ(published->at("diagnostics").size(), 1u);
    EXPECT_EQ(published->at("diagnostics")[0].at("severity"), 1);
    // Switched off, and the saved config re-lints the open document.
    esi::test::write_text(dir / ".esi-lint.yaml", "rules: { xml-hex-prefix: off }\n");
    client.notify("textDocument/didSave", {{"textDocument", {{"uri", esi::test::file_uri(dir / ".esi-lint.yaml")}}}});
    published = client.diagnostics_for(uri);
    ASSERT_TRUE(published);
    EXPECT_TRUE(published->at("diagnostics").empty()) << published->dump();
}

TEST(LspDiagnostics, DocumentsThatAreNotEsiFilesGetAFindingNotACrash) {
    LspClient client;
    client.initialize();
    const std::vector<std::string> texts = {"hello, this is not XML", "<EtherCATInfo><Vendor>", std::string("\x01\x02<\x00>", 5), "",
                                            "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a>\xC3\xA4</a>"};
    int n = 0;
    for (const std::string& text : texts) {
        const std::string uri = "file:///tmp/not-esi-" + std::to_string(n++) + ".xml";
        client.open(uri, text);
        const std::optional<json> published = client.diagnostics_for(uri);
        ASSERT_TRUE(published) << text;
        EXPECT_FALSE(published->at("diagnostics").empty()) << text;
    }
    // A YAML source that is not one.
    client.open("untitled:Untitled-1", "devices: [", 1, "yaml");
    EXPECT_TRUE(client.diagnostics_for("untitled:Untitled-1"));
    EXPECT_TRUE(client.request("shutdown").contains("result"));
}

TEST(LspDiagnostics, ClosingClearsTheDiagnostics) {
    LspClient client;
    client.initialize();
    const std::string uri = "file:///tmp/closing.xml";
    client.open(uri, sample_with_hex_prefix());
    ASSERT_TRUE(client.diagnostics_for(uri));
    client.notify("textDocument/didClose", {{"textDocument", {{"uri", uri}}}});
    const std::optional<json> cleared = client.diagnostics_for(uri);
    ASSERT_TRUE(cleared);
    EXPECT_TRUE(cleared->at("diagnostics").empty());
}

}  // namespace
