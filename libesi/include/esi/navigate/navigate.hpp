#pragma once
// Position-based editor features over one ESI file or YAML device source: hover, go to
// definition, references, completion and the outline. Plain structs in LSP units (see
// position.hpp); a language server maps them to JSON.
//
// An index is built once per document version from its text and answers every request of that
// version. Bad input (not XML, not YAML, truncated, positions past the end) gives an index that
// answers with empty results. References resolve within one device (or module): in a file of
// many devices, an object index means the object of the device whose element holds the cursor.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/navigate/position.hpp"

namespace esi::navigate {

class Index;  // opaque: built by build_index, read by the features below
struct IndexDeleter {
    void operator()(Index* index) const;
};
using IndexPtr = std::unique_ptr<Index, IndexDeleter>;

struct Hover {
    std::string markdown;
    Range range;  // the token hovered
};

enum class CompletionKind { object, data_type, element, value };

struct CompletionItem {
    std::string label;        // "#x6000", "UINT", "Entry"
    CompletionKind kind = CompletionKind::value;
    std::string detail;       // the object's name, a DataType's size …
    std::string insert_text;  // what replaces `replace`
    Range replace;            // the partial token at the cursor (empty at a blank)
};

enum class SymbolKind { device, module, sync_manager, pdo, pdo_entry, object, data_type };

struct Symbol {
    std::string name;
    std::string detail;
    SymbolKind kind = SymbolKind::object;
    Range range;            // the whole element
    Range selection_range;  // its index or name
    std::vector<Symbol> children;
};

// Never null. The path is only copied into the locations returned.
[[nodiscard]] IndexPtr build_index(std::string_view text, const std::string& path);

[[nodiscard]] std::optional<Hover> hover(const Index& index, Position position);
[[nodiscard]] std::vector<Location> definition(const Index& index, Position position);
[[nodiscard]] std::vector<Location> references(const Index& index, Position position, bool include_declaration);
[[nodiscard]] std::vector<CompletionItem> complete(const Index& index, Position position);
[[nodiscard]] std::vector<Symbol> outline(const Index& index);

}  // namespace esi::navigate
