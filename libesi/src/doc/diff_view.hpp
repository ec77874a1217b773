#pragma once
// The view diff.html.mustache renders (docs/esi-doc.md, "The diff page"): the change list with
// the breaking changes first and, per device, the pictures of what differs, old beside new.
// Apart from render_diff_html so that tests walk the very view the template sees.

#include <cstdint>
#include <string>

#include "doc/page_context.hpp"
#include "esi/diff/diff.hpp"
#include "esi/diff/report.hpp"

namespace esi::doc {

// `css` is inlined as the page's stylesheet; `lcid` is the language of names in the pictures.
[[nodiscard]] ViewValue diff_view(ViewArena& arena, const EsiDocument& old_document, const EsiDocument& new_document, const DiffResult& result,
                                  const DiffLabels& labels, std::uint32_t lcid, std::string css);

}  // namespace esi::doc
