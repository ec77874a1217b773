#pragma once
// A small LSP client for the tests: spawns esi-lsp with pipes on its standard input and output,
// frames and sends messages (or raw bytes, to test the framing), and reads what the server sends
// with a timeout, so a server that hangs fails the test instead of the test hanging.

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace esi::test {

class LspClient {
public:
    explicit LspClient(std::vector<std::string> extra_args = {"--debounce", "0"});
    ~LspClient();
    LspClient(const LspClient&) = delete;
    LspClient& operator=(const LspClient&) = delete;

    void send_raw(const std::string& bytes);
    void send(const nlohmann::json& message);
    // Sends a request (with the next id) and waits for its response, skipping notifications.
    nlohmann::json request(const std::string& method, nlohmann::json params = nlohmann::json::object(),
                           std::chrono::milliseconds timeout = std::chrono::seconds(20));
    void notify(const std::string& method, nlohmann::json params = nlohmann::json::object());
    // The next message from the server; nullopt on timeout or when the server closed its output.
    std::optional<nlohmann::json> receive(std::chrono::milliseconds timeout = std::chrono::seconds(20));
    // The next publishDiagnostics for `uri` (other messages are skipped).
    std::optional<nlohmann::json> diagnostics_for(const std::string& uri, std::chrono::milliseconds timeout = std::chrono::seconds(20));
    // initialize + initialized; returns initialize's result.
    nlohmann::json initialize();
    void open(const std::string& uri, const std::string& text, int version = 1, const std::string& language = "xml");
    // Closes the server's standard input.
    void close_input();
    // Waits for the server to end; its exit code, or nullopt if it is still running after `timeout`
    // (it is then killed). -signal when a signal ended it.
    std::optional<int> wait_exit(std::chrono::milliseconds timeout = std::chrono::seconds(20));

private:
    int pid_ = -1;
    int to_server_ = -1;
    int from_server_ = -1;
    std::string buffer_;
    int next_id_ = 1;
    bool exited_ = false;
};

std::string file_uri(const std::filesystem::path& path);

}  // namespace esi::test
