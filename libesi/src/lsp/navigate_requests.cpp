// The position-based requests: hover, definition, references, completion and documentSymbol,
// answered from esi::navigate (docs/navigate.md). This file is the JSON mapping only: LSP
// params in, the library's structs out as LSP results. A document's index is built on the first
// such request for its version and kept for the next ones until the document changes.

#include "esi/lsp/server.hpp"

namespace esi::lsp {

using Json = nlohmann::json;

namespace {

Json position_json(const navigate::Position& position) {
    return Json{{"line", position.line}, {"character", position.character}};
}

Json range_json(const navigate::Range& range) {
    return Json{{"start", position_json(range.start)}, {"end", position_json(range.end)}};
}

// LSP CompletionItemKind.
int completion_kind(navigate::CompletionKind kind) {
    switch (kind) {
        case navigate::CompletionKind::object: return 6;      // Variable
        case navigate::CompletionKind::data_type: return 22;  // Struct
        case navigate::CompletionKind::element: return 10;    // Property
        case navigate::CompletionKind::value: return 12;      // Value
    }
    return 1;
}

// LSP SymbolKind.
int symbol_kind(navigate::SymbolKind kind) {
    switch (kind) {
        case navigate::SymbolKind::device: return 5;          // Class
        case navigate::SymbolKind::module: return 2;          // Module
        case navigate::SymbolKind::sync_manager: return 11;   // Interface
        case navigate::SymbolKind::pdo: return 23;            // Struct
        case navigate::SymbolKind::pdo_entry: return 8;       // Field
        case navigate::SymbolKind::object: return 13;         // Variable
        case navigate::SymbolKind::data_type: return 26;      // TypeParameter
    }
    return 19;  // Object
}

Json symbol_json(const navigate::Symbol& symbol) {
    // LSP: a symbol's name must not be empty.
    Json out{{"name", symbol.name.empty() ? std::string("(unnamed)") : symbol.name},
             {"kind", symbol_kind(symbol.kind)},
             {"range", range_json(symbol.range)},
             {"selectionRange", range_json(symbol.selection_range)}};
    if (!symbol.detail.empty()) out["detail"] = symbol.detail;
    if (!symbol.children.empty()) {
        Json children = Json::array();
        for (const auto& child : symbol.children) children.push_back(symbol_json(child));
        out["children"] = std::move(children);
    }
    return out;
}

const Json* find_member(const Json& object, std::string_view key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

// textDocument.uri and position of TextDocumentPositionParams.
std::string document_uri(const Json& params) {
    const Json* document = find_member(params, "textDocument");
    const Json* uri = document ? find_member(*document, "uri") : nullptr;
    if (!uri || !uri->is_string()) throw ResponseError{error_code::invalid_params, "missing textDocument.uri"};
    return uri->get<std::string>();
}

navigate::Position document_position(const Json& params) {
    const Json* position = find_member(params, "position");
    const Json* line = position ? find_member(*position, "line") : nullptr;
    const Json* character = position ? find_member(*position, "character") : nullptr;
    const auto number = [](const Json* value) {
        if (!value || !(value->is_number_unsigned() || (value->is_number_integer() && value->get<std::int64_t>() >= 0)))
            throw ResponseError{error_code::invalid_params, "a position's line and character are non-negative integers"};
        return static_cast<std::uint32_t>(std::min<std::uint64_t>(value->get<std::uint64_t>(), UINT32_MAX));
    };
    return navigate::Position{number(line), number(character)};
}

}  // namespace

const navigate::Index* Server::navigation_index(const std::string& uri) {
    const std::optional<Document> document = documents_.find(uri);
    if (!document || !document->text) {
        navigation_.erase(uri);
        return nullptr;
    }
    auto it = navigation_.find(uri);
    if (it == navigation_.end() || it->second.version != document->version || it->second.text != document->text) {
        NavigationEntry entry{document->version, document->text, navigate::build_index(*document->text, uri)};
        it = navigation_.insert_or_assign(uri, std::move(entry)).first;
    }
    return it->second.index.get();
}

Json Server::hover(const Json& params) {
    const std::string uri = document_uri(params);
    const navigate::Position position = document_position(params);
    const navigate::Index* index = navigation_index(uri);
    if (!index) return nullptr;
    const auto result = navigate::hover(*index, position);
    if (!result) return nullptr;
    return Json{{"contents", {{"kind", "markdown"}, {"value", result->markdown}}}, {"range", range_json(result->range)}};
}

Json Server::definition(const Json& params) {
    const std::string uri = document_uri(params);
    const navigate::Position position = document_position(params);
    Json out = Json::array();
    if (const navigate::Index* index = navigation_index(uri))
        for (const auto& location : navigate::definition(*index, position))
            out.push_back(Json{{"uri", uri}, {"range", range_json(location.range)}});
    return out;
}

Json Server::references(const Json& params) {
    const std::string uri = document_uri(params);
    const navigate::Position position = document_position(params);
    bool include_declaration = false;
    if (const Json* context = find_member(params, "context"))
        if (const Json* include = find_member(*context, "includeDeclaration"); include && include->is_boolean())
            include_declaration = include->get<bool>();
    Json out = Json::array();
    if (const navigate::Index* index = navigation_index(uri))
        for (const auto& location : navigate::references(*index, position, include_declaration))
            out.push_back(Json{{"uri", uri}, {"range", range_json(location.range)}});
    return out;
}

Json Server::completion(const Json& params) {
    const std::string uri = document_uri(params);
    const navigate::Position position = document_position(params);
    Json items = Json::array();
    if (const navigate::Index* index = navigation_index(uri))
        for (const auto& item : navigate::complete(*index, position)) {
            Json out{{"label", item.label},
                     {"kind", completion_kind(item.kind)},
                     {"textEdit", {{"range", range_json(item.replace)}, {"newText", item.insert_text}}}};
            if (!item.detail.empty()) out["detail"] = item.detail;
            // Clients filter by the text the edit replaces; "#x60" must match "#x6000".
            out["filterText"] = item.label;
            items.push_back(std::move(out));
        }
    return Json{{"isIncomplete", false}, {"items", std::move(items)}};
}

Json Server::document_symbol(const Json& params) {
    const std::string uri = document_uri(params);
    Json out = Json::array();
    if (const navigate::Index* index = navigation_index(uri))
        for (const auto& symbol : navigate::outline(*index)) out.push_back(symbol_json(symbol));
    return out;
}

}  // namespace esi::lsp
