#pragma once
// The ESI library index: which file describes which device (identity -> file, offset).
//
// ESI libraries are hundreds of MB, and a network names a few dozen devices. The index lists
// every device of the library from a light scan of each file (esi/xml/identity_scan.hpp); only
// the files that hold the devices a network uses are then read into the model. The index is
// cached (one file under the cache directory, written atomically, with a checksum) and a file
// is scanned again when its path, size, modification time, change time or inode changed. The
// cache never changes a result: a cache that cannot be read, parsed or checked is ignored and
// rebuilt, and what a build or find takes from it is checked against the file itself
// (index_agrees_with_files); on any doubt the index is built again without the cache.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/xml/identity_scan.hpp"

namespace esi::net {

struct IndexedFile {
    std::string path;  // as found under a root (absolute or as the root was given), '/'-separated
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;
    std::int64_t ctime_ns = 0;  // status change: `cp -p` and `touch -r` keep mtime, never ctime
    std::uint64_t inode = 0;
    std::size_t root = 0;  // which root (in the order given) found it; not cached
    std::string problem;  // why no device of it is listed (unreadable, not well-formed); empty if fine
};

struct IndexedDevice {
    std::optional<std::uint32_t> vendor_id;
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision_no;
    std::string type;  // Type text
    std::string name;  // English Name
    std::string vendor_name;  // the file's Vendor/Name (English, else the first)
    std::size_t file = 0;  // into LibraryIndex::files
    std::size_t offset = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::size_t ordinal = 0;  // place among the file's devices
    // The device's HideType elements: revisions its vendor's catalogue shows it in place of
    // (resolve.cpp passes them over when no revision is asked for).
    std::vector<HiddenIdentity> hides;
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
    // Scan every file and write the cache anew without reading it (after the cache was found
    // to disagree with a file).
    bool rescan = false;
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

// True when each device, as the index lists it, is what its file holds now (the identity and
// Type text at its place, scanned afresh). Cheap: only the devices' files are read.
[[nodiscard]] bool index_agrees_with_files(const LibraryIndex& index, const std::vector<const IndexedDevice*>& devices);

// $XDG_CACHE_HOME/libesi, else $HOME/.cache/libesi; nullopt when neither variable is set.
[[nodiscard]] std::optional<std::filesystem::path> default_cache_dir();

// The cache file inside a cache directory.
[[nodiscard]] std::filesystem::path index_cache_file(const std::filesystem::path& cache_dir);

}  // namespace esi::net
