#include "io/directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <string>

namespace esi::io_detail {

namespace fs = std::filesystem;

struct DirectoryLock::Held {
    int fd = -1;
    fs::path file;
    LeftoverRegistration registration;
};

DirectoryLock::DirectoryLock(std::unique_ptr<Held> held) : held_(std::move(held)) {}
DirectoryLock::DirectoryLock(DirectoryLock&& other) noexcept = default;

namespace {

// A lock file that gets its name already locked: made under a name no other run knows, locked,
// then linked to `file` (which fails when it exists). -1 when `file` exists or on error.
int create_locked(const fs::path& file, LeftoverRegistration& registration, bool& exists, Diagnostics& diagnostics) {
    exists = false;
    static thread_local std::mt19937_64 random{std::random_device{}()};
    for (int attempt = 0; attempt < 16; ++attempt) {
        const fs::path unnamed = file.string() + "." + std::to_string(random() % 1000000000);
        int fd = -1;
        LeftoverRegistration unnamed_registration;
        {
            const DeferredSignals deferred;
            fd = ::open(unnamed.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
            if (fd >= 0) unnamed_registration = LeftoverRegistration(unnamed, LeftoverKind::file);
        }
        if (fd < 0) {
            if (errno == EEXIST) continue;
            if (errno != ENOENT)  // ENOENT: the directory was removed meanwhile; the caller retries
                diagnostics.emplace(Severity::error, "io-error", std::string("cannot create the lock file: ") + std::strerror(errno),
                                    file.string(), {});
            return -1;
        }
        ::flock(fd, LOCK_EX);  // uncontended: nobody else knows the name
        const DeferredSignals deferred;
        const bool linked = ::link(unnamed.c_str(), file.c_str()) == 0;
        const int link_error = errno;
        if (linked) registration = LeftoverRegistration(file, LeftoverKind::file);
        ::unlink(unnamed.c_str());
        unnamed_registration.release();
        if (linked) return fd;
        ::close(fd);
        if (link_error == EEXIST) exists = true;
        else
            diagnostics.emplace(Severity::error, "io-error", std::string("cannot create the lock file: ") + std::strerror(link_error),
                                file.string(), {});
        return -1;
    }
    diagnostics.emplace(Severity::error, "io-error", "cannot create the lock file", file.string(), {});
    return -1;
}

}  // namespace

std::optional<DirectoryLock> DirectoryLock::acquire(const fs::path& dir, CreatedDirectories& created, Diagnostics& diagnostics) {
    const fs::path file = dir / output_lock_file_name;
    auto held = std::make_unique<Held>();
    held->file = file;
    // Bounded: each retry means another run released the lock (removing its file) or removed the
    // directory it had created in the meantime.
    for (int attempt = 0; attempt < 1000; ++attempt) {
        if (!created.create(dir, diagnostics)) return std::nullopt;
        bool exists = false;
        const std::size_t errors = diagnostics.count(Severity::error);
        held->fd = create_locked(file, held->registration, exists, diagnostics);
        if (held->fd >= 0) return DirectoryLock(std::move(held));
        if (diagnostics.count(Severity::error) > errors) return std::nullopt;
        if (!exists) continue;
        // Another run holds it (or a run killed by SIGKILL left it): wait for it.
        const int fd = ::open(file.c_str(), O_RDWR | O_CLOEXEC);
        if (fd < 0) {
            if (errno == ENOENT) continue;  // released meanwhile
            diagnostics.emplace(Severity::error, "io-error", std::string("cannot open the lock file: ") + std::strerror(errno),
                                file.string(), {});
            return std::nullopt;
        }
        int locked = 0;
        while ((locked = ::flock(fd, LOCK_EX)) != 0 && errno == EINTR) {
        }
        if (locked != 0) {
            diagnostics.emplace(Severity::error, "io-error", std::string("cannot lock the output directory: ") + std::strerror(errno),
                                file.string(), {});
            ::close(fd);
            return std::nullopt;
        }
        // The run that held it removed the file before releasing it: then lock anew.
        const DeferredSignals deferred;
        struct stat locked_file {};
        struct stat named {};
        if (::fstat(fd, &locked_file) == 0 && ::stat(file.c_str(), &named) == 0 && locked_file.st_dev == named.st_dev &&
            locked_file.st_ino == named.st_ino) {
            held->fd = fd;
            held->registration = LeftoverRegistration(file, LeftoverKind::file);
            return DirectoryLock(std::move(held));
        }
        ::close(fd);
    }
    diagnostics.emplace(Severity::error, "io-error", "cannot lock the output directory: its lock file keeps changing", file.string(), {});
    return std::nullopt;
}

DirectoryLock::~DirectoryLock() {
    if (!held_) return;
    const DeferredSignals deferred;
    ::unlink(held_->file.c_str());  // while still held: see the header
    held_->registration.release();
    ::close(held_->fd);
}

}  // namespace esi::io_detail
