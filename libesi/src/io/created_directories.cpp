#include "io/created_directories.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace esi::io_detail {

namespace fs = std::filesystem;

bool CreatedDirectories::create(const fs::path& dir, Diagnostics& diagnostics) {
    if (dir.empty()) return true;
    std::vector<fs::path> missing;  // innermost first
    std::error_code ec;
    for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        const DeferredSignals deferred;  // made and registered as one step
        if (::mkdir(it->c_str(), 0777) == 0) {
            created_.push_back({*it, LeftoverRegistration(*it, LeftoverKind::directory)});
        } else if (errno != EEXIST) {  // EEXIST: a concurrent run made it, so it is not ours to remove
            diagnostics.emplace(Severity::error, "io-error", std::string("cannot create directory: ") + std::strerror(errno),
                                it->string(), {});
            return false;
        }
    }
    if (!fs::is_directory(dir, ec)) {
        diagnostics.emplace(Severity::error, "io-error", "cannot create directory: a file of that name exists", dir.string(), {});
        return false;
    }
    return true;
}

void CreatedDirectories::remove() noexcept {
    for (auto it = created_.rbegin(); it != created_.rend(); ++it) {
        ::rmdir(it->path.c_str());
        it->registration.release();
    }
    created_.clear();
}

void CreatedDirectories::keep() noexcept { created_.clear(); }

}  // namespace esi::io_detail
