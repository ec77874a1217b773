#include "esi/io/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <set>
#include <string_view>

#include "io/created_directories.hpp"
#include "io/directory_lock.hpp"
#include "io/leftover_registry.hpp"
#include "io/unchanged_file.hpp"

namespace esi {

namespace {

using io_detail::CreatedDirectories;
using io_detail::LeftoverKind;
using io_detail::LeftoverRegistration;

std::string error_text() { return std::strerror(errno); }

std::filesystem::path directory_of(const std::filesystem::path& target) {
    return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

// A file written in full beside its target, not yet in place. On Linux it is an unnamed file
// (O_TMPFILE) that gets a name only just before the rename, so a process killed while writing
// (SIGKILL, SIGXFSZ, out of memory) leaves no temporary file behind; elsewhere, or on file
// systems without O_TMPFILE, it is a hidden named file that is removed on every error path.
struct Staged {
    int fd = -1;                    // open unnamed file (O_TMPFILE), or -1
    std::filesystem::path named;    // named temporary file, or empty
    LeftoverRegistration leftover;  // the named file, removed if the run is interrupted
};

bool write_all(int fd, const std::string& content, std::string& error) {
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            error = error_text();
            return false;
        }
        data += n;
        left -= static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) {
        error = error_text();
        return false;
    }
    return true;
}

std::filesystem::path temporary_name(const std::filesystem::path& target) {
    static thread_local std::mt19937_64 random{std::random_device{}()};
    return directory_of(target) / ("." + target.filename().string() + ".tmp" + std::to_string(random() % 1000000000));
}

bool stage_named(const std::filesystem::path& target, const std::string& content, Staged& staged, std::string& error) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        const std::filesystem::path temporary = temporary_name(target);
        int fd = -1;
        {
            const io_detail::DeferredSignals deferred;  // created and registered as one step
            fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
            if (fd >= 0) staged.leftover = LeftoverRegistration(temporary, LeftoverKind::file);
        }
        if (fd < 0) {
            if (errno == EEXIST) continue;
            error = error_text();
            return false;
        }
        const bool written = write_all(fd, content, error);
        if (::close(fd) != 0 && written) error = error_text();
        if (!written || !error.empty()) {
            ::unlink(temporary.c_str());
            staged.leftover.release();
            return false;
        }
        staged.named = temporary;
        return true;
    }
    error = "cannot create a temporary file";
    return false;
}

bool stage(const std::filesystem::path& target, const std::string& content, Staged& staged, std::string& error) {
#ifdef O_TMPFILE
    const int fd = ::open(directory_of(target).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
    if (fd >= 0) {
        if (!write_all(fd, content, error)) {
            ::close(fd);  // an unnamed file vanishes with its last descriptor
            return false;
        }
        staged.fd = fd;
        return true;
    }
    // Kernels or file systems without O_TMPFILE answer EOPNOTSUPP, EISDIR or EINVAL.
    if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) {
        error = error_text();
        return false;
    }
#endif
    return stage_named(target, content, staged, error);
}

void discard(Staged& staged) {
    if (staged.fd >= 0) ::close(staged.fd);
    if (!staged.named.empty()) ::unlink(staged.named.c_str());
    staged.leftover.release();
    staged.fd = -1;
    staged.named.clear();
}

// Gives an unnamed file its temporary name (through /proc/self/fd, which needs no privilege,
// unlike linkat's AT_EMPTY_PATH) and moves the named file over the target.
bool commit(const std::filesystem::path& target, Staged& staged, std::string& error) {
    if (staged.fd >= 0) {
        const std::string fd_path = "/proc/self/fd/" + std::to_string(staged.fd);
        for (int attempt = 0; attempt < 16 && staged.named.empty(); ++attempt) {
            const std::filesystem::path temporary = temporary_name(target);
            const io_detail::DeferredSignals deferred;  // named and registered as one step
            if (::linkat(AT_FDCWD, fd_path.c_str(), AT_FDCWD, temporary.c_str(), AT_SYMLINK_FOLLOW) == 0) {
                staged.named = temporary;
                staged.leftover = LeftoverRegistration(temporary, LeftoverKind::file);
            } else if (errno != EEXIST) {
                break;
            }
        }
        if (staged.named.empty()) {
            error = "cannot name the temporary file: " + error_text();
            return false;
        }
        ::close(staged.fd);
        staged.fd = -1;
    }
    const io_detail::DeferredSignals deferred;  // renamed and forgotten as one step
    if (std::rename(staged.named.c_str(), target.c_str()) != 0) {
        error = error_text();
        return false;
    }
    staged.named.clear();
    staged.leftover.release();
    return true;
}

// The previous file at a target, kept under a second name while a set is renamed into place.
struct Backup {
    std::filesystem::path name;     // empty: the target did not exist (or could not be kept)
    LeftoverRegistration leftover;  // removed if the run is interrupted
};

void keep_previous(const std::filesystem::path& target, Backup& backup) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        std::filesystem::path name = temporary_name(target);
        name += ".previous";
        const io_detail::DeferredSignals deferred;  // linked and registered as one step
        if (::link(target.c_str(), name.c_str()) == 0) {
            backup.name = name;
            backup.leftover = LeftoverRegistration(name, LeftoverKind::file);
            return;
        }
        if (errno != EEXIST) return;  // no target (ENOENT), or a file system without hard links
    }
}

// Puts the previous file back, or removes a target that did not exist before the run.
void roll_back(const std::filesystem::path& target, Backup& backup) {
    const io_detail::DeferredSignals deferred;
    if (!backup.name.empty()) {
        if (std::rename(backup.name.c_str(), target.c_str()) == 0) {
            backup.name.clear();
            backup.leftover.release();
        }
    } else {
        ::unlink(target.c_str());
    }
}

void drop(Backup& backup) {
    if (backup.name.empty()) return;
    const io_detail::DeferredSignals deferred;
    ::unlink(backup.name.c_str());
    backup.name.clear();
    backup.leftover.release();
}

// Whether `name` is one of the names this file gives beside `target`: ".NAME.tmpDIGITS" (a
// complete new copy, named just before its rename) or the same with ".previous" (the kept
// previous file of a set).
bool is_temporary_name_of(const std::string& name, const std::filesystem::path& target) {
    const std::string prefix = "." + target.filename().string() + ".tmp";
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
    std::string_view rest(name);
    rest.remove_prefix(prefix.size());
    if (rest.size() > 9 && rest.substr(rest.size() - 9) == ".previous") rest.remove_suffix(9);
    return !rest.empty() && std::all_of(rest.begin(), rest.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A run killed by SIGKILL cannot remove what it named: a complete copy about to be renamed, or
// the second name of a previous file. The next run into the same directory, holding its lock
// (so no other run is writing there), removes those names of its own targets.
void remove_leftovers_of_killed_runs(const std::vector<OutputFile>& files) {
    std::set<std::filesystem::path> directories;
    for (const auto& file : files) directories.insert(directory_of(file.path));
    for (const auto& directory : directories) {
        std::error_code ec;
        std::vector<std::filesystem::path> leftovers;
        for (std::filesystem::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            for (const auto& file : files)
                if (directory_of(file.path) == directory && is_temporary_name_of(name, file.path)) {
                    leftovers.push_back(it->path());
                    break;
                }
        }
        for (const auto& leftover : leftovers) ::unlink(leftover.c_str());
    }
}

}  // namespace

Diagnostics write_files_atomically(const std::vector<OutputFile>& files) {
    Diagnostics diagnostics;
    std::vector<Staged> staged(files.size());
    std::vector<bool> unchanged(files.size(), false);  // already holds its bytes: left alone
    CreatedDirectories created;  // removed again when the set cannot be written
    auto discard_all = [&] {
        for (auto& s : staged) discard(s);
        created.remove();
    };
    for (std::size_t i = 0; i < files.size(); ++i) {
        const auto& file = files[i];
        std::error_code ec;
        // Caught before anything is staged: a rename onto a directory would fail only after
        // earlier files of the set were already in place.
        if (std::filesystem::is_directory(file.path, ec)) {
            diagnostics.emplace(Severity::error, "io-error", "cannot write: is a directory", file.path.string(), {});
            break;
        }
        if (io_detail::holds_exactly(file.path, file.content)) {
            unchanged[i] = true;
            continue;
        }
        if (file.path.has_parent_path() && !created.create(file.path.parent_path(), diagnostics)) break;
        std::string error;
        if (!stage(file.path, file.content, staged[i], error)) {
            diagnostics.emplace(Severity::error, "io-error", "cannot write: " + error, file.path.string(), {});
            break;
        }
    }
    if (diagnostics.has_errors()) {
        discard_all();
        return diagnostics;
    }
    // Every file is complete on disk; now move them into place. Each target that exists keeps a
    // second name (a hard link) until the whole set is in place, so that a rename failing
    // part-way (an immutable file, a full directory) rolls back what was already renamed and
    // the previous set stays whole.
    // One file to replace needs no second name: its rename either happens or not. (A SIGKILL
    // cannot be caught, so every second name made is one a killed run leaves behind.)
    std::vector<Backup> backups(files.size());
    const auto to_replace = std::count(unchanged.begin(), unchanged.end(), false);
    for (std::size_t i = 0; i < files.size() && to_replace > 1; ++i)
        if (!unchanged[i]) keep_previous(files[i].path, backups[i]);
    std::set<std::filesystem::path> directories;
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (unchanged[i]) continue;
        std::string error;
        if (!commit(files[i].path, staged[i], error)) {
            diagnostics.emplace(Severity::error, "io-error", "cannot replace file: " + error, files[i].path.string(), {});
            for (std::size_t j = i; j-- > 0;)
                if (!unchanged[j]) roll_back(files[j].path, backups[j]);
            for (Backup& b : backups) drop(b);
            discard_all();
            return diagnostics;
        }
        directories.insert(directory_of(files[i].path));
    }
    for (Backup& b : backups) drop(b);
    created.keep();
    // Make the renames durable too: a crash right after returning must not bring back old files.
    for (const auto& dir : directories) {
        const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd < 0) continue;
        ::fsync(fd);
        ::close(fd);
    }
    return diagnostics;
}

Diagnostics write_file_atomically(const std::filesystem::path& path, const std::string& content) {
    return write_files_atomically({OutputFile{path, content}});
}

Diagnostics write_output_set(const std::filesystem::path& root, const std::vector<OutputFile>& files) {
    Diagnostics diagnostics;
    CreatedDirectories created;
    std::optional<io_detail::DirectoryLock> lock = io_detail::DirectoryLock::acquire(root, created, diagnostics);
    if (!lock) {
        created.remove();
        return diagnostics;
    }
    remove_leftovers_of_killed_runs(files);
    diagnostics = write_files_atomically(files);
    if (diagnostics.has_errors()) {
        lock.reset();  // removes the lock file, so that a root this run created is empty again
        created.remove();
    } else {
        created.keep();
    }
    return diagnostics;
}

}  // namespace esi
