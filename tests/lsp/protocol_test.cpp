// esi-lsp as an editor meets it: the lifecycle, JSON-RPC errors, broken framing and a client that
// goes away, spoken by a small client over the server's pipes.

#include <gtest/gtest.h>

#include "lsp/lsp_client.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::LspClient;
using nlohmann::json;

int error_code(const json& response) { return response.at("error").at("code").get<int>(); }

TEST(LspLifecycle, RequestsBeforeInitializeAreRefused) {
    LspClient client;
    const json response = client.request("textDocument/codeAction", json::object());
    EXPECT_EQ(error_code(response), -32002);
    const json shutdown = client.request("shutdown");
    EXPECT_EQ(error_code(shutdown), -32002);
    client.initialize();  // the server is still usable
}

TEST(LspLifecycle, CapabilitiesAreWhatIsImplemented) {
    LspClient client;
    const json result = client.initialize();
    const json& caps = result.at("capabilities");
    EXPECT_EQ(caps.at("textDocumentSync").at("change"), 2);  // incremental
    EXPECT_TRUE(caps.at("textDocumentSync").at("openClose").get<bool>());
    EXPECT_EQ(caps.at("codeActionProvider").at("codeActionKinds"), json::array({"quickfix"}));
    // Every request of the table is announced (tests/lsp/navigate_protocol_test.cpp asks them).
    for (const char* present : {"hoverProvider", "definitionProvider", "referencesProvider", "completionProvider",
                                "documentSymbolProvider"})
        EXPECT_TRUE(caps.contains(present)) << present;
    EXPECT_EQ(result.at("serverInfo").at("name"), "esi-lsp");
}

TEST(LspLifecycle, ShutdownThenExitIsExitCodeZero) {
    LspClient client;
    client.initialize();
    const json shutdown = client.request("shutdown");
    EXPECT_TRUE(shutdown.contains("result"));
    EXPECT_TRUE(shutdown.at("result").is_null());
    // After shutdown, requests are refused.
    EXPECT_EQ(error_code(client.request("textDocument/codeAction", json::object())), -32600);
    client.notify("exit");
    EXPECT_EQ(client.wait_exit(), 0);
}

TEST(LspLifecycle, ExitWithoutShutdownIsExitCodeOne) {
    LspClient client;
    client.initialize();
    client.notify("exit");
    EXPECT_EQ(client.wait_exit(), 1);
}

TEST(LspLifecycle, SecondInitializeIsAnError) {
    LspClient client;
    client.initialize();
    EXPECT_EQ(error_code(client.request("initialize", json::object())), -32600);
}

TEST(LspProtocol, UnknownMethodIsMethodNotFound) {
    LspClient client;
    client.initialize();
    EXPECT_EQ(error_code(client.request("textDocument/noSuchThing", json::object())), -32601);
    // An unknown notification is ignored; the server goes on.
    client.notify("$/noSuchNotification", json::object());
    client.notify("$/cancelRequest", {{"id", 99}});
    EXPECT_EQ(error_code(client.request("esi/nothing")), -32601);
}

TEST(LspProtocol, MalformedJsonRpcGetsErrorsAndTheSessionGoesOn) {
    LspClient client;
    client.initialize();
    const auto raw = [&](const std::string& body) {
        client.send_raw("Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
        const std::optional<json> reply = client.receive();
        EXPECT_TRUE(reply.has_value()) << body;
        return reply.value_or(json::object());
    };
    json reply = raw("{\"jsonrpc\": \"2.0\", \"id\": 1, \"method\": ");
    EXPECT_EQ(error_code(reply), -32700);
    EXPECT_TRUE(reply.at("id").is_null());
    EXPECT_EQ(error_code(raw("[1, 2, 3]")), -32600);
    EXPECT_EQ(error_code(raw("{\"jsonrpc\": \"2.0\", \"id\": 7}")), -32600);
    EXPECT_EQ(error_code(raw("{\"jsonrpc\": \"2.0\", \"id\": {\"a\": 1}, \"method\": \"shutdown\"}")), -32600);
    EXPECT_EQ(error_code(raw("{\"jsonrpc\": \"2.0\", \"id\": 8, \"method\": 42}")), -32600);
    EXPECT_EQ(error_code(raw("{\"jsonrpc\": \"2.0\", \"id\": 9, \"method\": \"textDocument/codeAction\", \"params\": 5}")), -32602);
    // Nested a million deep, and bytes that are not UTF-8: errors, not a stack overflow or a crash.
    EXPECT_EQ(error_code(raw(std::string(1'000'000, '[') + std::string(1'000'000, ']'))), -32600);
    EXPECT_EQ(error_code(raw("{\"jsonrpc\": \"2.0\", \"id\": 10, \"method\": \"\xFF\xFE\"}")), -32700);
    // Params of the wrong shape: InvalidParams, not a crash.
    EXPECT_EQ(error_code(client.request("textDocument/codeAction", {{"textDocument", 3}})), -32602);
    EXPECT_EQ(error_code(client.request("textDocument/codeAction",
                                        {{"textDocument", {{"uri", "file:///x.xml"}}},
                                         {"range", {{"start", {{"line", -1}, {"character", 0}}}, {"end", 0}}}})),
              -32602);
    // A notification with bad params is dropped silently; the server still answers.
    client.notify("textDocument/didOpen", {{"textDocument", "nonsense"}});
    client.notify("textDocument/didChange", {{"textDocument", {{"uri", "file:///never-opened.xml"}, {"version", 2}}},
                                             {"contentChanges", json::array({{{"text", "x"}}})}});
    EXPECT_TRUE(client.request("shutdown").contains("result"));
}

TEST(LspFraming, BadHeadersAreSkippedAndTheNextMessageIsRead) {
    LspClient client;
    client.initialize();
    client.send_raw("Content-Type: application/vscode-jsonrpc\r\n\r\n");  // no length
    std::optional<json> reply = client.receive();
    ASSERT_TRUE(reply);
    EXPECT_EQ(error_code(*reply), -32700);
    client.send_raw("Content-Length: twelve\r\n\r\n");
    reply = client.receive();
    ASSERT_TRUE(reply);
    EXPECT_EQ(error_code(*reply), -32700);
    // Garbage before a header: skipped up to the header.
    client.send_raw("this is not a header at all {\"id\": 1}\r\n");
    const json ping = client.request("esi/ping");  // after the garbage, a well-framed request is answered
    EXPECT_EQ(error_code(ping), -32601);
    // A message split into single bytes arrives whole.
    const std::string body = R"({"jsonrpc":"2.0","id":"split","method":"esi/ping"})";
    const std::string framed = "content-length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
    for (const char c : framed) client.send_raw(std::string(1, c));
    std::optional<json> split;
    while ((split = client.receive()) && !split->contains("id")) {}
    ASSERT_TRUE(split);
    EXPECT_EQ(split->at("id"), "split");
}

TEST(LspFraming, ClientThatDisappearsMidMessageEndsTheServerCleanly) {
    LspClient client;
    client.initialize();
    client.send_raw("Content-Length: 500\r\n\r\n{\"jsonrpc\": \"2.0\", \"id\": 2, \"met");
    client.close_input();
    EXPECT_EQ(client.wait_exit(std::chrono::seconds(10)), 1);  // no shutdown was asked: 1, and no signal
}

TEST(LspFraming, ClientThatDisappearsInTheHeaderEndsTheServerCleanly) {
    LspClient client;
    client.send_raw("Content-Len");
    client.close_input();
    EXPECT_EQ(client.wait_exit(std::chrono::seconds(10)), 1);
}

TEST(LspFraming, ClientThatGoesAwayAfterShutdownGetsExitCodeZero) {
    LspClient client;
    client.initialize();
    client.request("shutdown");
    client.close_input();
    EXPECT_EQ(client.wait_exit(std::chrono::seconds(10)), 0);
}

}  // namespace
