#pragma once
// The documents the editor has open, as the editor holds them (not as they are on disk): opened
// with their full text, changed by whole-text replacement or by range edits (LSP's full and
// incremental sync), closed. Each version's text is an immutable snapshot that the lint worker
// can read while the next change arrives.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "esi/lsp/position.hpp"

namespace esi::lsp {

struct Document {
    std::string uri;
    std::string language_id;
    std::int64_t version = 0;
    std::shared_ptr<const std::string> text;
};

// One contentChange of didChange: a range edit, or (no range) the whole new text.
struct ContentChange {
    std::optional<Range> range;
    std::string text;
};

class DocumentStore {
public:
    void open(std::string uri, std::string language_id, std::int64_t version, std::string text);
    // Applies the changes in order (each range refers to the text the previous one left). False
    // when the document is not open.
    bool change(const std::string& uri, std::int64_t version, const std::vector<ContentChange>& changes);
    void close(const std::string& uri);
    [[nodiscard]] std::optional<Document> find(const std::string& uri) const;
    [[nodiscard]] std::vector<std::string> uris() const;

private:
    std::map<std::string, Document, std::less<>> documents_;
};

// The file-system path of a file: URI ("file:///a%20b/c.xml" -> "/a b/c.xml"); nullopt for other
// schemes (an untitled buffer).
[[nodiscard]] std::optional<std::string> path_of_uri(std::string_view uri);

}  // namespace esi::lsp
