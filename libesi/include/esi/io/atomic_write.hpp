#pragma once
// Output files are written whole or not at all: each goes to a temporary file beside its
// target and is renamed into place only when every file of the set has been written. A failed
// or interrupted run leaves the targets as they were.

#include <filesystem>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"

namespace esi {

struct OutputFile {
    std::filesystem::path path;
    std::string content;
};

// Writes all files or none. Creates missing parent directories. Errors come back as io-error
// diagnostics; on error no target has been replaced.
[[nodiscard]] Diagnostics write_files_atomically(const std::vector<OutputFile>& files);

[[nodiscard]] Diagnostics write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace esi
