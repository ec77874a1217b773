#pragma once
// Inputs are never outputs: a tool must not replace a file it reads (esi-gen --import X -o X would
// turn an ESI file into its YAML import). An output names an input when both resolve to
// the same path through symbolic links, or, where both exist, are the same file on disk (the same
// device and inode: hard links, bind mounts).

#include <filesystem>
#include <vector>

#include "esi/diagnostic.hpp"

namespace esi {

[[nodiscard]] bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// An `output-is-input` error at `output` for the first input it names; empty when it names none.
[[nodiscard]] Diagnostics refuse_output_over_input(const std::filesystem::path& output,
                                                   const std::vector<std::filesystem::path>& inputs);

}  // namespace esi
