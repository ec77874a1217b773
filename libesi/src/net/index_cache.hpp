#pragma once
// The on-disk form of the library index: one text file, one line per file and per device,
// strictly parsed. Anything unexpected (another version, a truncated or edited file) makes
// the whole cache unusable, and the index is rebuilt from the files. The last line carries a
// checksum (FNV-1a, 64 bits) of every line before it, so that an edited cache, however
// well-formed, is not trusted either.
//
//   libesi-esi-index 3
//   F <size> <mtime_ns> <ctime_ns> <inode> <device count> <path>
//   P <problem>                                   (optional, after F)
//   D <vendor|-> <product|-> <revision|-> <offset> <line> <column> <ordinal> <type>\t<name>\t<vendor name>
//   H <product|-> <revision|->                    (one per HideType of the device before it)
//   end <file count> <checksum, 16 hex digits>
//
// Text fields escape '\\', tab and newline as \\\\, \\t and \\n.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/net/library_index.hpp"

namespace esi::net {

struct CachedFile {
    IndexedFile file;
    std::vector<IndexedDevice> devices;  // `file` members are meaningless here
};

using IndexCache = std::map<std::string, CachedFile, std::less<>>;

// nullopt when the text is not a valid cache.
[[nodiscard]] std::optional<IndexCache> parse_index_cache(std::string_view text);
[[nodiscard]] std::string format_index_cache(const IndexCache& cache);

}  // namespace esi::net
