#include "esi/codegen/template_lookup.hpp"

#include <string>
#include <system_error>

#include "esi/io/read_file.hpp"

namespace esi::codegen {

namespace fs = std::filesystem;

fs::path installed_template_dir(const fs::path& executable) {
    return (executable.parent_path() / ".." / "share" / "libesi" / "templates").lexically_normal();
}

fs::path source_template_dir() { return ESI_TEMPLATE_DIR; }

std::vector<fs::path> template_search_path(const std::vector<fs::path>& user_dirs, const std::optional<fs::path>& executable) {
    std::vector<fs::path> dirs = user_dirs;
    std::error_code ec;
    if (executable) {
        const fs::path installed = installed_template_dir(*executable);
        if (fs::is_directory(installed, ec)) dirs.push_back(installed);
    }
    const fs::path source = source_template_dir();
    if (fs::is_directory(source, ec)) dirs.push_back(source);
    return dirs;
}

std::optional<fs::path> find_template(std::string_view name, const std::vector<fs::path>& dirs) {
    std::error_code ec;
    for (const auto& dir : dirs) {
        const fs::path candidate = dir / fs::path(name);
        if (fs::is_regular_file(candidate, ec)) return candidate;
    }
    return std::nullopt;
}

TemplateFile load_template(std::string_view name, const std::vector<fs::path>& dirs, std::string_view tool, Diagnostics& diagnostics) {
    TemplateFile out;
    const auto path = find_template(name, dirs);
    if (!path) {
        std::string searched;
        for (const auto& d : dirs) searched += (searched.empty() ? "" : ", ") + d.string();
        diagnostics.emplace(Severity::error, std::string(tool) + "-template-missing",
                            "template '" + std::string(name) + "' not found (searched: " + (searched.empty() ? "nothing" : searched) + ")",
                            "", {});
        return out;
    }
    out.path = *path;
    std::string error;
    const auto text = read_file_bytes(*path, error);
    if (!text) {
        diagnostics.emplace(Severity::error, "io-error", error, path->string(), {});
        return out;
    }
    mustache::ParseResult parsed = mustache::parse(*text);
    if (!parsed.parsed) {
        diagnostics.emplace(Severity::error, std::string(tool) + "-template-error", parsed.error, path->string(), parsed.pos);
        return out;
    }
    out.parsed = std::move(parsed.parsed);
    return out;
}

}  // namespace esi::codegen
