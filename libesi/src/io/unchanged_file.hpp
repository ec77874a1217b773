#pragma once
// Whether a target already holds exactly the bytes a run would write. Such a file is left alone
// (not replaced, so its modification time stays): a build system that compares times (make,
// Ninja) then does not recompile a firmware whose generated sources did not change.

#include <filesystem>
#include <string_view>

namespace esi::io_detail {

// True when `path` is a readable regular file (symbolic links followed) whose content equals
// `content`; false when it differs, is missing or cannot be read (the caller then writes it).
[[nodiscard]] bool holds_exactly(const std::filesystem::path& path, std::string_view content);

}  // namespace esi::io_detail
