#pragma once
// The templates of esi-doc's pages (templates/doc/): device.html.mustache, index.html.mustache,
// diff.html.mustache and the stylesheet page.css that every page inlines, each looked up by name
// along the search list so that a vendor can replace any one of them.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/codegen/mustache.hpp"
#include "esi/diagnostic.hpp"

namespace esi::doc {

using codegen::mustache::Template;

[[nodiscard]] std::optional<Template> load_page_template(std::string_view name, const std::vector<std::filesystem::path>& dirs,
                                                         Diagnostics& diagnostics);

// page.css as written; nullopt (with a diagnostic) when it is missing or unreadable.
[[nodiscard]] std::optional<std::string> load_stylesheet(const std::vector<std::filesystem::path>& dirs, Diagnostics& diagnostics);

}  // namespace esi::doc
