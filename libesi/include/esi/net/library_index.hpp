#pragma once
// The ESI library index: which file describes which device (identity -> file, offset).
//
// ESI libraries are hundreds of MB, and a network names a few dozen devices. The index lists
// every device of the library from a light scan of each file (esi/xml/identity_scan.hpp); only
// the files that hold the devices a network uses are then read into the model. The index is
// cached (one file under the cache directory, written atomically) and a file is scanned again
// only when its path, size or modification time changed. A cache that cannot be read or
// parsed is ignored and rebuilt.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"

namespace esi::net {

struct IndexedFile {
    std::string path;  // as found under a root (absolute or as the root was given), '/'-separated
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;
    std::string problem;  // why no device of it is listed (unreadable, not well-formed); empty if fine
};

struct IndexedDevice {
    std::optional<std::uint32_t> vendor_id;
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision_no;
    std::string type;  // Type text
    std::string name;  // English Name
    std::size_t file = 0;  // into LibraryIndex::files
    std::size_t offset = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::size_t ordinal = 0;  // place among the file's devices
};

struct LibraryIndex {
    std::vector<IndexedFile> files;      // sorted by path
    std::vector<IndexedDevice> devices;  // by file, then document order
    std::vector<std::string> roots;      // where it looked, as given

    [[nodiscard]] const IndexedFile& file_of(const IndexedDevice& device) const { return files[device.file]; }
};

struct IndexOptions {
    // Where the cache lives; nullopt: no cache (every file is scanned).
    std::optional<std::filesystem::path> cache_dir;
};

struct IndexStats {
    std::size_t files = 0;    // files in the index
    std::size_t scanned = 0;  // files scanned in this run
    std::size_t cached = 0;   // files taken from the cache
    bool cache_ignored = false;  // a cache existed but could not be used
    bool cache_written = false;
};

struct IndexResult {
    LibraryIndex index;
    IndexStats stats;
    Diagnostics diagnostics;  // io problems with roots, files not indexed, cache problems
};

// Files and folders: a file is indexed as it is (ESI XML, or a YAML device source); a folder is
// searched recursively for *.xml files. Paths are sorted so that the index is deterministic.
[[nodiscard]] IndexResult build_library_index(const std::vector<std::filesystem::path>& roots, const IndexOptions& options);

// $XDG_CACHE_HOME/libesi, else $HOME/.cache/libesi; nullopt when neither variable is set.
[[nodiscard]] std::optional<std::filesystem::path> default_cache_dir();

// The cache file inside a cache directory.
[[nodiscard]] std::filesystem::path index_cache_file(const std::filesystem::path& cache_dir);

}  // namespace esi::net
