#pragma once
// esi-lsp's server: JSON-RPC 2.0 over the framed stream (esi/lsp/framing.hpp), the LSP
// lifecycle, the document store and the requests. Requests are answered on the calling thread;
// linting runs on the lint worker (esi/lsp/lint_worker.hpp), which publishes diagnostics itself.
//
// Requests and notifications are dispatched through one table each (server.cpp): a handler is one
// entry, with the server capability it advertises, so initialize announces exactly what the
// table holds.

#include <nlohmann/json.hpp>

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "esi/lsp/document_store.hpp"
#include "esi/lsp/framing.hpp"
#include "esi/lsp/lint_worker.hpp"
#include "esi/navigate/navigate.hpp"

namespace esi::lsp {

// JSON-RPC and LSP error codes.
namespace error_code {
inline constexpr int parse_error = -32700;
inline constexpr int invalid_request = -32600;
inline constexpr int method_not_found = -32601;
inline constexpr int invalid_params = -32602;
inline constexpr int internal_error = -32603;
inline constexpr int server_not_initialized = -32002;
inline constexpr int request_cancelled = -32800;
}  // namespace error_code

// Thrown by a handler to answer with an error.
struct ResponseError {
    int code = error_code::internal_error;
    std::string message;
};

struct ServerOptions {
    // How long a document's text must be still before it is linted.
    std::chrono::milliseconds debounce{100};
};

class Server {
public:
    Server(MessageWriter& out, ServerOptions options);
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    // Handles one frame from the reader: a message, or a framing problem (answered with an error).
    void handle(const Frame& frame);
    // `exit` arrived.
    [[nodiscard]] bool exited() const { return state_ == State::exited; }
    // The process's exit code: 0 once `shutdown` was answered, 1 otherwise (LSP's rule for
    // `exit`, and for a client that went away without it).
    [[nodiscard]] int exit_code() const { return shutdown_received_ ? 0 : 1; }

    using Json = nlohmann::json;
    using RequestHandler = Json (Server::*)(const Json& params);
    using NotificationHandler = void (Server::*)(const Json& params);

private:
    enum class State { uninitialized, running, shut_down, exited };

    void handle_message(const Json& message);
    void respond(const Json& id, Json result);
    void respond_error(const Json& id, int code, const std::string& message);
    void notify(std::string_view method, Json params);

    // Requests.
    Json initialize(const Json& params);
    Json shutdown(const Json& params);
    Json code_action(const Json& params);
    // The position-based requests (navigate_requests.cpp).
    Json hover(const Json& params);
    Json definition(const Json& params);
    Json references(const Json& params);
    Json completion(const Json& params);
    Json document_symbol(const Json& params);
    // Notifications.
    void initialized(const Json& params);
    void exit(const Json& params);
    void cancel_request(const Json& params);
    void did_open(const Json& params);
    void did_change(const Json& params);
    void did_close(const Json& params);
    void did_save(const Json& params);

    void submit_lint(const Document& document);
    void publish(LintResult result);  // on the worker thread

    struct RequestEntry;
    struct NotificationEntry;
    static const std::map<std::string, RequestEntry, std::less<>>& requests();
    static const std::map<std::string, NotificationEntry, std::less<>>& notifications();

    MessageWriter& out_;
    ServerOptions options_;
    State state_ = State::uninitialized;
    bool shutdown_received_ = false;
    DocumentStore documents_;  // the main thread's only
    std::mutex results_mutex_;
    std::map<std::string, LintResult, std::less<>> results_;  // the latest published lint per document
    std::unique_ptr<LintWorker> worker_;

    // The navigation index of a document's version, built on the first request that needs it.
    struct NavigationEntry {
        std::int64_t version = 0;
        std::shared_ptr<const std::string> text;  // the snapshot indexed
        navigate::IndexPtr index;
    };
    // The index of the open document's current version; null when the document is not open.
    const navigate::Index* navigation_index(const std::string& uri);
    std::map<std::string, NavigationEntry, std::less<>> navigation_;  // the main thread's only
};

// Reads messages until `exit` or the end of input and returns the exit code.
[[nodiscard]] int run_server(ReadSome in, MessageWriter& out, ServerOptions options);

}  // namespace esi::lsp
