#pragma once
// The directories a writing run created. A run that fails removes them again (those that are
// empty), so a failed run leaves the tree as it found it; while the run lasts they are
// registered as leftovers, so that an interrupted run removes them too (esi/io/leftovers.hpp).

#include <filesystem>
#include <vector>

#include "esi/diagnostic.hpp"
#include "io/leftover_registry.hpp"

namespace esi::io_detail {

class CreatedDirectories {
public:
    CreatedDirectories() = default;
    CreatedDirectories(const CreatedDirectories&) = delete;
    CreatedDirectories& operator=(const CreatedDirectories&) = delete;

    // Creates `dir` and its missing parents; false and an io-error when it cannot, or when
    // `dir` exists and is not a directory.
    bool create(const std::filesystem::path& dir, Diagnostics& diagnostics);
    // The run failed: removes the created directories that are empty, innermost first.
    void remove() noexcept;
    // The run succeeded: they stay (also what happens when the object goes away).
    void keep() noexcept;

private:
    struct Created {
        std::filesystem::path path;
        LeftoverRegistration registration;
    };
    std::vector<Created> created_;  // outermost first
};

}  // namespace esi::io_detail
