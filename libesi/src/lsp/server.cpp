#include "esi/lsp/server.hpp"

#include <filesystem>

#include "esi/lsp/code_actions.hpp"
#include "esi/version.hpp"

namespace esi::lsp {

using Json = nlohmann::json;

struct Server::RequestEntry {
    RequestHandler handler;
    // The server capability the handler stands for: its key in ServerCapabilities (empty: none)
    // and the value announced.
    std::string_view capability;
    Json capability_value;
};

struct Server::NotificationEntry {
    NotificationHandler handler;
};

// The requests the server answers. A new feature is one entry here: its method, handler and
// capability (textDocument/hover -> "hoverProvider", definition -> "definitionProvider",
// references -> "referencesProvider", completion -> "completionProvider", documentSymbol ->
// "documentSymbolProvider").
const std::map<std::string, Server::RequestEntry, std::less<>>& Server::requests() {
    static const std::map<std::string, RequestEntry, std::less<>> table = {
        {"initialize", {&Server::initialize, {}, {}}},
        {"shutdown", {&Server::shutdown, {}, {}}},
        {"textDocument/codeAction", {&Server::code_action, "codeActionProvider", {{"codeActionKinds", {"quickfix"}}}}},
        {"textDocument/hover", {&Server::hover, "hoverProvider", true}},
        {"textDocument/definition", {&Server::definition, "definitionProvider", true}},
        {"textDocument/references", {&Server::references, "referencesProvider", true}},
        {"textDocument/completion", {&Server::completion, "completionProvider", {{"triggerCharacters", {"<", "#"}}}}},
        {"textDocument/documentSymbol", {&Server::document_symbol, "documentSymbolProvider", true}},
    };
    return table;
}

// Notifications; one not listed here is ignored, as the protocol asks.
const std::map<std::string, Server::NotificationEntry, std::less<>>& Server::notifications() {
    static const std::map<std::string, NotificationEntry, std::less<>> table = {
        {"initialized", {&Server::initialized}},
        {"exit", {&Server::exit}},
        {"$/cancelRequest", {&Server::cancel_request}},
        {"textDocument/didOpen", {&Server::did_open}},
        {"textDocument/didChange", {&Server::did_change}},
        {"textDocument/didClose", {&Server::did_close}},
        {"textDocument/didSave", {&Server::did_save}},
    };
    return table;
}

namespace {

const Json& member(const Json& object, std::string_view key) {
    if (!object.is_object()) throw ResponseError{error_code::invalid_params, "params must be an object"};
    const auto it = object.find(key);
    if (it == object.end()) throw ResponseError{error_code::invalid_params, "missing " + std::string(key)};
    return *it;
}

std::string string_member(const Json& object, std::string_view key) {
    const Json& value = member(object, key);
    if (!value.is_string()) throw ResponseError{error_code::invalid_params, std::string(key) + " must be a string"};
    return value.get<std::string>();
}

std::int64_t version_member(const Json& object) {
    const Json& value = member(object, "version");
    if (!value.is_number_integer()) throw ResponseError{error_code::invalid_params, "version must be an integer"};
    return value.get<std::int64_t>();
}

Position position_member(const Json& object) {
    const auto number = [](const Json& value) {
        if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0))
            throw ResponseError{error_code::invalid_params, "a position's line and character are non-negative integers"};
        return static_cast<std::uint32_t>(std::min<std::uint64_t>(value.get<std::uint64_t>(), UINT32_MAX));
    };
    return {number(member(object, "line")), number(member(object, "character"))};
}

Range range_member(const Json& object) {
    const Json& range = member(object, "range");
    return {position_member(member(range, "start")), position_member(member(range, "end"))};
}

// .esi-lint.yaml is a config, not a device source: not linted as one.
bool is_lint_config(const std::string& uri) { return uri.size() >= 13 && uri.ends_with("/.esi-lint.yaml"); }

}  // namespace

Server::Server(MessageWriter& out, ServerOptions options) : out_(out), options_(options) {
    worker_ = std::make_unique<LintWorker>(options_.debounce, [this](LintResult result) { publish(std::move(result)); });
}

Server::~Server() { worker_.reset(); }

void Server::respond(const Json& id, Json result) {
    out_.write(Json{{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}}.dump(-1, ' ', false, Json::error_handler_t::replace));
}

void Server::respond_error(const Json& id, int code, const std::string& message) {
    out_.write(Json{{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}}.dump(
        -1, ' ', false, Json::error_handler_t::replace));
}

void Server::notify(std::string_view method, Json params) {
    out_.write(Json{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}.dump(
        -1, ' ', false, Json::error_handler_t::replace));
}

void Server::handle(const Frame& frame) {
    switch (frame.kind) {
        case Frame::Kind::end_of_input: return;
        case Frame::Kind::bad_header:
        case Frame::Kind::oversize: respond_error(nullptr, error_code::parse_error, frame.problem); return;
        case Frame::Kind::message: break;
    }
    Json message = Json::parse(frame.body, nullptr, false);
    if (message.is_discarded()) {
        respond_error(nullptr, error_code::parse_error, "the message is not JSON");
        return;
    }
    handle_message(message);
}

void Server::handle_message(const Json& message) {
    if (!message.is_object()) {
        respond_error(nullptr, error_code::invalid_request, "a message is a JSON object (batches are not part of LSP)");
        return;
    }
    const auto id_it = message.find("id");
    const auto method_it = message.find("method");
    const bool has_id = id_it != message.end();
    if (has_id && !id_it->is_string() && !id_it->is_number_integer()) {
        respond_error(nullptr, error_code::invalid_request, "id must be an integer or a string");
        return;
    }
    const Json id = has_id ? *id_it : Json(nullptr);
    if (method_it == message.end()) {
        if (has_id && (message.contains("result") || message.contains("error"))) return;  // a response; we ask nothing
        respond_error(id, error_code::invalid_request, "no method");
        return;
    }
    if (!method_it->is_string()) {
        respond_error(id, error_code::invalid_request, "method must be a string");
        return;
    }
    const std::string method = method_it->get<std::string>();
    const auto params_it = message.find("params");
    const Json params = params_it == message.end() ? Json::object() : *params_it;
    if (!params.is_object() && !params.is_array()) {
        if (has_id) respond_error(id, error_code::invalid_params, "params must be an object or an array");
        return;
    }

    if (!has_id) {
        const auto entry = notifications().find(method);
        if (entry == notifications().end()) return;
        // Before initialize only exit is heard; after shutdown, only exit.
        if (method != "exit" && state_ != State::running) return;
        try {
            (this->*entry->second.handler)(params);
        } catch (const ResponseError&) {  // a notification has no answer to carry the error
        } catch (const Json::exception&) {
        }
        return;
    }

    const auto entry = requests().find(method);
    if (state_ == State::uninitialized && method != "initialize") {
        respond_error(id, error_code::server_not_initialized, "initialize first");
        return;
    }
    if (state_ == State::shut_down) {
        respond_error(id, error_code::invalid_request, "the server is shutting down");
        return;
    }
    if (entry == requests().end()) {
        respond_error(id, error_code::method_not_found, "unknown method " + method);
        return;
    }
    try {
        respond(id, (this->*entry->second.handler)(params));
    } catch (const ResponseError& error) {
        respond_error(id, error.code, error.message);
    } catch (const Json::exception& error) {
        respond_error(id, error_code::invalid_params, error.what());
    } catch (const std::exception& error) {
        respond_error(id, error_code::internal_error, error.what());
    }
}

Json Server::initialize(const Json&) {
    if (state_ != State::uninitialized) throw ResponseError{error_code::invalid_request, "initialize was already received"};
    Json capabilities = {
        {"positionEncoding", "utf-16"},
        // Incremental sync (2); opened and closed documents; saves without their text.
        {"textDocumentSync", {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
    };
    for (const auto& [method, entry] : requests())
        if (!entry.capability.empty()) capabilities[std::string(entry.capability)] = entry.capability_value;
    state_ = State::running;
    return {{"capabilities", std::move(capabilities)}, {"serverInfo", {{"name", "esi-lsp"}, {"version", std::string(version())}}}};
}

Json Server::shutdown(const Json&) {
    state_ = State::shut_down;
    shutdown_received_ = true;
    return nullptr;
}

void Server::initialized(const Json&) {}

void Server::exit(const Json&) { state_ = State::exited; }

// Requests are answered in the order they arrive, each before the next is read, so a cancel
// always comes for a request already answered: nothing to do.
void Server::cancel_request(const Json&) {}

void Server::submit_lint(const Document& document) {
    if (is_lint_config(document.uri)) return;
    worker_->submit(LintRequest{document.uri, path_of_uri(document.uri).value_or(std::string{}), document.version, document.text});
}

void Server::did_open(const Json& params) {
    const Json& item = member(params, "textDocument");
    const std::string uri = string_member(item, "uri");
    const Json& language = item.contains("languageId") ? item["languageId"] : Json("");
    documents_.open(uri, language.is_string() ? language.get<std::string>() : "", version_member(item), string_member(item, "text"));
    submit_lint(*documents_.find(uri));
}

void Server::did_change(const Json& params) {
    const Json& item = member(params, "textDocument");
    const std::string uri = string_member(item, "uri");
    const Json& changes = member(params, "contentChanges");
    if (!changes.is_array()) throw ResponseError{error_code::invalid_params, "contentChanges must be an array"};
    std::vector<ContentChange> parsed;
    for (const Json& change : changes) {
        ContentChange c;
        if (change.contains("range")) c.range = range_member(change);
        c.text = string_member(change, "text");
        parsed.push_back(std::move(c));
    }
    if (!documents_.change(uri, version_member(item), parsed)) return;
    submit_lint(*documents_.find(uri));
}

void Server::did_close(const Json& params) {
    const std::string uri = string_member(member(params, "textDocument"), "uri");
    documents_.close(uri);
    worker_->forget(uri);
    navigation_.erase(uri);
    {
        const std::lock_guard lock(results_mutex_);
        results_.erase(uri);
    }
    // The editor keeps a closed file's problems until told otherwise.
    notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", Json::array()}});
}

void Server::did_save(const Json& params) {
    const std::string uri = string_member(member(params, "textDocument"), "uri");
    if (is_lint_config(uri)) {
        // A changed config changes every open document's findings.
        for (const std::string& open : documents_.uris())
            if (const std::optional<Document> document = documents_.find(open)) submit_lint(*document);
        return;
    }
    if (const std::optional<Document> document = documents_.find(uri)) submit_lint(*document);
}

void Server::publish(LintResult result) {
    Json params = publish_params(result);
    {
        const std::lock_guard lock(results_mutex_);
        results_.insert_or_assign(result.uri, std::move(result));
    }
    notify("textDocument/publishDiagnostics", std::move(params));
}

Json Server::code_action(const Json& params) {
    const std::string uri = string_member(member(params, "textDocument"), "uri");
    const Range range = range_member(params);
    const std::optional<Document> document = documents_.find(uri);
    if (!document) return Json::array();
    if (const auto context = params.find("context"); context != params.end() && context->contains("only")) {
        const Json& only = (*context)["only"];
        const bool wants_quickfix = only.is_array() && std::any_of(only.begin(), only.end(), [](const Json& kind) {
            return kind.is_string() && (kind.get<std::string>() == "quickfix" || kind.get<std::string>().empty());
        });
        if (!wants_quickfix) return Json::array();
    }
    const std::lock_guard lock(results_mutex_);
    const auto it = results_.find(uri);
    // The findings of an older text would place their edits wrongly: none until the lint of this
    // version is in.
    if (it == results_.end() || it->second.version != document->version || it->second.text != document->text)
        return Json::array();
    return code_actions(it->second, range);
}

int run_server(ReadSome in, MessageWriter& out, ServerOptions options) {
    MessageReader reader(std::move(in));
    Server server(out, options);
    for (;;) {
        const Frame frame = reader.next();
        if (frame.kind == Frame::Kind::end_of_input) return server.exit_code();
        server.handle(frame);
        if (server.exited()) return server.exit_code();
    }
}

}  // namespace esi::lsp
