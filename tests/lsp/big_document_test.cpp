// A catalogue of about 40 MB (the corpus's largest Beckhoff catalogue, its devices repeated) does
// not block the server: while it is linted the server answers other requests, and of two versions
// sent in quick succession only the newer one's findings are published.

#include <gtest/gtest.h>

#include "esi/encoding.hpp"
#include "core/sanitizers.hpp"
#include "lsp/lsp_client.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::LspClient;
using nlohmann::json;

std::string synthetic_catalogue(std::size_t target_bytes) {
    const std::string text =
        esi::decode_xml_bytes(esi::test::read_text(esi::test::corpus_esi_dir() / "Beckhoff__EL3xxx__dls-ethercat.xml")).utf8;
    const std::size_t open = text.find("<Devices>");
    const std::size_t close = text.rfind("</Devices>");
    if (open == std::string::npos || close == std::string::npos) return {};
    const std::size_t inner = open + std::string_view("<Devices>").size();
    const std::string devices = text.substr(inner, close - inner);
    std::string out = text.substr(0, close);
    while (out.size() < target_bytes) out += devices;
    out += text.substr(close);
    return out;
}

// Under the sanitizers (the CI's second tree) a quarter of the size shows the same and keeps the
// test in seconds; the server's code paths do not depend on the size.
constexpr std::size_t target_megabytes() { return ESI_ADDRESS_SANITIZER ? 10 : 40; }

TEST(LspBigDocument, FortyMegabytesDoNotBlockTheServer) {
    ESI_REQUIRE_CORPUS();
    const std::string big = synthetic_catalogue(target_megabytes() << 20);
    ASSERT_GT(big.size(), target_megabytes() << 20);
    // Debounced as an editor would be: the open and the edit right after it cost one lint.
    LspClient client({"--debounce", "300"});
    client.initialize();
    const std::string uri = "file:///tmp/esi-lsp-big-catalogue.xml";
    client.open(uri, big);
    // An edit while the first version is being linted: a comment after the declaration.
    const std::size_t declaration_end = big.find("?>") + 2;
    ASSERT_LT(declaration_end, 200u);
    client.notify("textDocument/didChange",
                  {{"textDocument", {{"uri", uri}, {"version", 2}}},
                   {"contentChanges", json::array({{{"range", {{"start", {{"line", 0}, {"character", declaration_end}}},
                                                               {"end", {{"line", 0}, {"character", declaration_end}}}}},
                                                    {"text", "<!-- edited -->"}}})}});
    // Answered while the worker lints: before the findings of 40 MB are published.
    client.send({{"jsonrpc", "2.0"}, {"id", "during-lint"}, {"method", "textDocument/codeAction"},
                 {"params", {{"textDocument", {{"uri", uri}}},
                             {"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}},
                             {"context", {{"diagnostics", json::array()}}}}}});
    std::optional<json> message;
    while ((message = client.receive(std::chrono::seconds(60))) && !message->contains("id"))
        EXPECT_NE(message->value("method", ""), "textDocument/publishDiagnostics") << "the lint went before the request";
    ASSERT_TRUE(message);
    EXPECT_EQ(message->at("id"), "during-lint");
    EXPECT_TRUE(message->at("result").empty());  // no findings of this version yet: no actions
    // Only the newest version is published.
    const std::optional<json> published = client.diagnostics_for(uri, std::chrono::seconds(120));
    ASSERT_TRUE(published);
    EXPECT_EQ(published->at("version"), 2);
    EXPECT_EQ(client.request("shutdown", json::object(), std::chrono::seconds(120)).at("result"), nullptr);
    client.notify("exit");
    EXPECT_EQ(client.wait_exit(std::chrono::seconds(120)), 0);
}

}  // namespace
