#pragma once
// esi-diff --format html: the report as one self-contained HTML page. The breaking changes (and
// the revision errors) come first; then each device with its changes and, where its process data
// differs, the SyncManager images and PDOs of both files side by side with added, removed, moved
// and resized entries marked (esi/doc/bit_layout.hpp). Rendered from templates/doc/diff.html.mustache.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/diff/diff.hpp"
#include "esi/diff/report.hpp"
#include "esi/model/language.hpp"

namespace esi::doc {

struct DiffHtmlOptions {
    std::uint32_t lcid = default_lcid;                 // language of names in the pictures
    std::vector<std::filesystem::path> template_dirs;  // the search list (esi/doc/datasheet.hpp template_search_path)
};

struct DiffHtml {
    std::string html;         // empty when `diagnostics` has errors
    Diagnostics diagnostics;  // doc-template-missing, doc-template-error, io-error
};

// `result` is diff_documents(old_document, new_document) (or diff_files with keep_documents).
[[nodiscard]] DiffHtml render_diff_html(const EsiDocument& old_document, const EsiDocument& new_document, const DiffResult& result,
                                        const DiffLabels& labels, const DiffHtmlOptions& options);

}  // namespace esi::doc
