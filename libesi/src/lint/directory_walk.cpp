#include "lint/directory_walk.hpp"

#include <algorithm>
#include <cctype>

namespace esi::lint_detail {

namespace fs = std::filesystem;

namespace {

bool skipped_folder(const fs::path& dir) {
    const std::string name = dir.filename().string();
    if (!name.empty() && name.front() == '.') return true;
    std::error_code ec;
    return fs::exists(dir / "CMakeCache.txt", ec);
}

bool is_xml(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == ".xml";
}

void cannot_read(const fs::path& dir, const std::error_code& ec, Diagnostics& diagnostics) {
    diagnostics.emplace(Severity::error, "io-error", "cannot read directory: " + ec.message(), dir.string(), {});
}

void walk(const fs::path& dir, std::vector<fs::path>& found, Diagnostics& diagnostics) {
    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    if (ec) {
        cannot_read(dir, ec, diagnostics);
        return;
    }
    std::vector<fs::path> subdirectories;
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) break;
        const fs::directory_entry& entry = *it;
        std::error_code type_ec;
        const bool directory = !entry.is_symlink(type_ec) && entry.is_directory(type_ec);
        if (directory) {
            if (!skipped_folder(entry.path())) subdirectories.push_back(entry.path());
        } else if (is_xml(entry.path()) && entry.is_regular_file(type_ec)) {
            found.push_back(entry.path());
        }
    }
    if (ec) cannot_read(dir, ec, diagnostics);
    for (const auto& sub : subdirectories) walk(sub, found, diagnostics);
}

}  // namespace

void collect_xml_files(const fs::path& dir, std::vector<fs::path>& out, Diagnostics& diagnostics) {
    std::vector<fs::path> found;
    const std::size_t errors = diagnostics.count(Severity::error);
    walk(dir, found, diagnostics);
    if (found.empty() && diagnostics.count(Severity::error) == errors)
        diagnostics.emplace(Severity::error, "io-error",
                            "no ESI files (*.xml) in this directory (hidden folders and CMake build trees are not searched)",
                            dir.string(), {});
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
}

}  // namespace esi::lint_detail
