#include "doc/page_templates.hpp"

#include <system_error>

#include "esi/codegen/template_lookup.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/io/read_file.hpp"

namespace esi::doc {

namespace fs = std::filesystem;

std::vector<fs::path> template_search_path(const std::vector<fs::path>& user_dirs, const std::optional<fs::path>& executable) {
    std::vector<fs::path> dirs = user_dirs;
    std::error_code ec;
    for (const fs::path& root : codegen::template_search_path({}, executable))
        if (fs::is_directory(root / "doc", ec)) dirs.push_back(root / "doc");
    return dirs;
}

std::optional<Template> load_page_template(std::string_view name, const std::vector<fs::path>& dirs, Diagnostics& diagnostics) {
    return codegen::load_template(name, dirs, "doc", diagnostics).parsed;
}

std::optional<std::string> load_stylesheet(const std::vector<fs::path>& dirs, Diagnostics& diagnostics) {
    constexpr std::string_view name = "page.css";
    const auto path = codegen::find_template(name, dirs);
    if (!path) {
        diagnostics.emplace(Severity::error, "doc-template-missing", "stylesheet 'page.css' not found in the template directories", "", {});
        return std::nullopt;
    }
    std::string error;
    auto text = read_file_bytes(*path, error);
    if (!text) diagnostics.emplace(Severity::error, "io-error", error, path->string(), {});
    return text;
}

}  // namespace esi::doc
