#pragma once
// An exclusive lock on an output directory, so that two runs writing into it (two targets of a
// parallel build, an editor and a build) take turns instead of leaving a mix of both sets: an
// flock on the lock file `.esi-output.lock` inside the directory. The file is removed while the
// lock is still held, when it is released; a run that waited on it then finds the path gone or
// naming another file and locks anew, so removing it is safe. A run killed by SIGKILL leaves the
// empty file behind, which the next run takes over.

#include <filesystem>
#include <memory>
#include <optional>

#include "esi/diagnostic.hpp"
#include "io/created_directories.hpp"

namespace esi::io_detail {

inline constexpr const char* output_lock_file_name = ".esi-output.lock";

class DirectoryLock {
public:
    // Creates the directory when missing (into `created`) and waits for the lock; nothing and an
    // io-error when it cannot.
    [[nodiscard]] static std::optional<DirectoryLock> acquire(const std::filesystem::path& dir, CreatedDirectories& created,
                                                              Diagnostics& diagnostics);
    ~DirectoryLock();
    DirectoryLock(DirectoryLock&& other) noexcept;
    DirectoryLock& operator=(DirectoryLock&&) = delete;
    DirectoryLock(const DirectoryLock&) = delete;
    DirectoryLock& operator=(const DirectoryLock&) = delete;

private:
    struct Held;
    explicit DirectoryLock(std::unique_ptr<Held> held);
    std::unique_ptr<Held> held_;
};

}  // namespace esi::io_detail
