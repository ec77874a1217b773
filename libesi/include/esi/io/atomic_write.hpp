#pragma once
// Output files are written whole or not at all: each goes to a temporary file beside its
// target and is renamed into place only when every file of the set has been written. A failed
// or interrupted run leaves the targets as they were. A target that already holds exactly the
// bytes to write is left alone, so its modification time stays and a build that depends on it
// does not rebuild.

#include <filesystem>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"

namespace esi {

struct OutputFile {
    std::filesystem::path path;
    std::string content;
};

// Writes all files or none. Creates missing parent directories (and removes them again when the
// set cannot be written). Errors come back as io-error diagnostics; on error no target has been
// replaced. While a temporary file has a name it is registered as a leftover
// (esi/io/leftovers.hpp), so an interrupted run can remove it.
[[nodiscard]] Diagnostics write_files_atomically(const std::vector<OutputFile>& files);

// The same for one run's set of outputs under `root` (a tool's -o directory): the set is written
// under an exclusive lock on `root` (a lock file inside it), so two runs into one directory take
// turns and the files both write all come from one of them; a failed run also removes `root`
// when it created it. Holding the lock, it first removes what a run killed by SIGKILL left of
// these targets (a complete copy under its temporary name, a previous file's second name).
[[nodiscard]] Diagnostics write_output_set(const std::filesystem::path& root, const std::vector<OutputFile>& files);

[[nodiscard]] Diagnostics write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace esi
