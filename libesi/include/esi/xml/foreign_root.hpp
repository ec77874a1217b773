#pragma once
// XML files that sit next to ESI files but describe something else: a network configuration
// (ENI), a master's own configuration, init-command lists. A directory of device files often holds
// them too, so esi-lint recognises them by their root element and skips them on a directory walk
// rather than failing the run; named on the command line they get an error that says what they are.

#include <optional>
#include <string>
#include <string_view>

namespace esi {

struct ForeignDocument {
    std::string root;       // the root element's name as written (without a namespace prefix)
    std::string_view what;  // what the file is, for a message: "an ENI (ETG.2100 network configuration)"
};

// What kind of non-ESI file has this root element; nullopt for a root not known here (which may
// be a misspelt ESI root, and stays an xml-unknown-root finding).
[[nodiscard]] std::optional<ForeignDocument> recognise_foreign_root(std::string_view root_name);

// The name of the first element of an XML text (after the declaration, comments, processing
// instructions and a DOCTYPE), without its namespace prefix; empty when there is none.
[[nodiscard]] std::string first_element_name(std::string_view xml);

// recognise_foreign_root(first_element_name(xml)).
[[nodiscard]] std::optional<ForeignDocument> recognise_foreign_document(std::string_view xml);

}  // namespace esi
