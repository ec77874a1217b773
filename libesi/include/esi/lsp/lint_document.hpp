#pragma once
// esi-lint on a document as the editor holds it: the text in memory, not the file on disk, under
// the config esi-lint would use for the file's path (the nearest .esi-lint.yaml), with the same
// rules, severities and inline suppressions (esi::lint_bytes, one pipeline for both).

#include <string>
#include <string_view>

#include "esi/lint/lint.hpp"

namespace esi::lsp {

struct DocumentLint {
    FileReport report;
    // The fixes' byte offsets address the document's text. The editor sends the text as UTF-8; a
    // file declaring ISO-8859-1 is handed to the linter in that encoding (so that it decodes to the
    // editor's text again), and when that cannot be done the offsets are not trusted.
    bool fixes_apply = false;
    bool xml = true;  // an ESI file, not a YAML device source (suppression comments are XML's)
};

// `path` is the file's path (for the config lookup and the messages); empty for a buffer that has
// none, linted under the default config.
[[nodiscard]] DocumentLint lint_document(std::string_view text, const std::string& path);

}  // namespace esi::lsp
