#include "esi/lsp/document_store.hpp"

namespace esi::lsp {

void DocumentStore::open(std::string uri, std::string language_id, std::int64_t version, std::string text) {
    Document document{uri, std::move(language_id), version, std::make_shared<const std::string>(std::move(text))};
    documents_.insert_or_assign(std::move(uri), std::move(document));
}

bool DocumentStore::change(const std::string& uri, std::int64_t version, const std::vector<ContentChange>& changes) {
    const auto it = documents_.find(uri);
    if (it == documents_.end()) return false;
    Document& document = it->second;
    std::string text = *document.text;  // the old snapshot may still be being linted
    for (const ContentChange& change : changes) {
        if (!change.range) {
            text = change.text;
            continue;
        }
        const std::size_t from = offset_of(text, change.range->start);
        const std::size_t to = std::max(from, offset_of(text, change.range->end));
        text.replace(from, to - from, change.text);
    }
    document.version = version;
    document.text = std::make_shared<const std::string>(std::move(text));
    return true;
}

void DocumentStore::close(const std::string& uri) {
    const auto it = documents_.find(uri);
    if (it != documents_.end()) documents_.erase(it);
}

std::optional<Document> DocumentStore::find(const std::string& uri) const {
    const auto it = documents_.find(uri);
    if (it == documents_.end()) return std::nullopt;
    return it->second;
}

std::vector<std::string> DocumentStore::uris() const {
    std::vector<std::string> out;
    for (const auto& [uri, document] : documents_) out.push_back(uri);
    return out;
}

std::optional<std::string> path_of_uri(std::string_view uri) {
    constexpr std::string_view scheme = "file://";
    if (uri.substr(0, scheme.size()) != scheme) return std::nullopt;
    uri.remove_prefix(scheme.size());
    // file://host/path: only the local host.
    const std::size_t slash = uri.find('/');
    if (slash == std::string_view::npos) return std::nullopt;
    const std::string_view host = uri.substr(0, slash);
    if (!host.empty() && host != "localhost") return std::nullopt;
    uri.remove_prefix(slash);
    std::string path;
    path.reserve(uri.size());
    const auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            path += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            path += uri[i];
        }
    }
    return path;
}

}  // namespace esi::lsp
