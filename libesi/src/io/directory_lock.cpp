#include "io/directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace esi::io_detail {

namespace fs = std::filesystem;

struct DirectoryLock::Held {
    int fd = -1;
    fs::path file;
    LeftoverRegistration registration;
};

DirectoryLock::DirectoryLock(std::unique_ptr<Held> held) : held_(std::move(held)) {}
DirectoryLock::DirectoryLock(DirectoryLock&& other) noexcept = default;

std::optional<DirectoryLock> DirectoryLock::acquire(const fs::path& dir, CreatedDirectories& created, Diagnostics& diagnostics) {
    const fs::path file = dir / output_lock_file_name;
    // Bounded: each retry means another run released the lock (or removed the directory it had
    // created) in the meantime.
    for (int attempt = 0; attempt < 1000; ++attempt) {
        if (!created.create(dir, diagnostics)) return std::nullopt;
        const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0) {
            if (errno == ENOENT) continue;  // the directory was removed meanwhile
            diagnostics.emplace(Severity::error, "io-error", std::string("cannot create the lock file: ") + std::strerror(errno),
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
        struct stat held {};
        struct stat named {};
        if (::fstat(fd, &held) == 0 && ::stat(file.c_str(), &named) == 0 && held.st_dev == named.st_dev && held.st_ino == named.st_ino) {
            auto state = std::make_unique<Held>();
            state->fd = fd;
            state->file = file;
            state->registration = LeftoverRegistration(file, LeftoverKind::file);
            return DirectoryLock(std::move(state));
        }
        ::close(fd);
    }
    diagnostics.emplace(Severity::error, "io-error", "cannot lock the output directory: its lock file keeps changing", file.string(), {});
    return std::nullopt;
}

DirectoryLock::~DirectoryLock() {
    if (!held_) return;
    ::unlink(held_->file.c_str());  // while still held: see the header
    held_->registration.release();
    ::close(held_->fd);
}

}  // namespace esi::io_detail
