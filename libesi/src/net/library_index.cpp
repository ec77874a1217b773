#include "esi/net/library_index.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

#include "esi/device_selector.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/io/read_file.hpp"
#include "esi/load/document.hpp"
#include "esi/xml/identity_scan.hpp"
#include "index_cache.hpp"

namespace esi::net {

namespace fs = std::filesystem;

namespace {

bool has_extension(const fs::path& path, std::initializer_list<std::string_view> extensions) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return std::find(extensions.begin(), extensions.end(), ext) != extensions.end();
}

struct FoundFile {
    std::string path;
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;
    std::int64_t ctime_ns = 0;
    std::uint64_t inode = 0;
    std::size_t root = 0;
};

// What the cache is keyed on. The change time cannot be set by a user: a file rewritten and
// given back its size and modification time (`cp -p`, `touch -r`) still changes it.
bool stat_file(const fs::path& path, FoundFile& out, std::string& why) {
    out.path = path.generic_string();
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        why = "cannot read this file's size or time; not indexed";
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        why = "not a regular file; not indexed";
        return false;
    }
    out.size = static_cast<std::uint64_t>(st.st_size);
    out.mtime_ns = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
    out.ctime_ns = static_cast<std::int64_t>(st.st_ctim.tv_sec) * 1'000'000'000 + st.st_ctim.tv_nsec;
    out.inode = static_cast<std::uint64_t>(st.st_ino);
    return true;
}

// The files under the roots: given files as they are, *.xml below given folders.
std::vector<FoundFile> find_files(const std::vector<fs::path>& roots, Diagnostics& diagnostics) {
    std::vector<FoundFile> found;
    std::set<std::string> seen;
    std::size_t rank = 0;
    auto add = [&](const fs::path& path) {
        FoundFile file;
        std::string why;
        if (!stat_file(path, file, why)) {
            diagnostics.emplace(Severity::warning, "net-index", why, path.generic_string(), {});
            return;
        }
        file.root = rank;
        if (seen.insert(file.path).second) found.push_back(std::move(file));
    };
    for (std::size_t r = 0; r < roots.size(); ++r) {
        const fs::path& root = roots[r];
        rank = r;
        std::error_code ec;
        const fs::file_status status = fs::status(root, ec);
        if (ec || !fs::exists(status)) {
            diagnostics.emplace(Severity::error, "io-error", "no such file or folder (an ESI library path)", root.generic_string(), {});
            continue;
        }
        if (!fs::is_directory(status)) {
            add(root);
            continue;
        }
        fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
        for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
            std::error_code type_ec;
            if (it->is_regular_file(type_ec) && has_extension(it->path(), {".xml"})) add(it->path());
        }
        if (ec)
            diagnostics.emplace(Severity::warning, "net-index", "could not list the whole folder: " + ec.message(),
                                root.generic_string(), {});
    }
    std::sort(found.begin(), found.end(), [](const FoundFile& a, const FoundFile& b) { return a.path < b.path; });
    return found;
}

// The devices of a YAML device source (small files: read whole through the load layer).
CachedFile scan_yaml_source(const FoundFile& found) {
    CachedFile out;
    LoadedDocument loaded = load_document_file(found.path);
    if (!loaded.usable()) {
        out.file.problem = "not a usable device source";
        for (const Diagnostic& d : loaded.diagnostics)
            if (d.severity == Severity::error) {
                out.file.problem = format_location(d.path, d.pos) + ": " + d.message;
                break;
            }
        return out;
    }
    std::size_t ordinal = 0;
    for (const Device* device : select_devices(*loaded.document, std::nullopt)) {
        IndexedDevice d;
        const EtherCATInfo* info = loaded.document->info_of(*device);
        if (info && info->vendor) {
            d.vendor_id = info->vendor->id;
            d.vendor_name = primary_text(info->vendor->names);
        }
        d.product_code = device->type.product_code;
        d.revision_no = device->type.revision_no;
        d.type = device->type.text;
        d.name = primary_text(device->names);
        d.line = device->pos.line;
        d.column = device->pos.column;
        d.ordinal = ordinal++;
        out.devices.push_back(std::move(d));
    }
    return out;
}

void set_key(IndexedFile& file, const FoundFile& found) {
    file.path = found.path;
    file.size = found.size;
    file.mtime_ns = found.mtime_ns;
    file.ctime_ns = found.ctime_ns;
    file.inode = found.inode;
}

CachedFile scan_file(const FoundFile& found) {
    if (has_extension(found.path, {".yaml", ".yml"})) {
        CachedFile out = scan_yaml_source(found);
        set_key(out.file, found);
        return out;
    }
    CachedFile out;
    set_key(out.file, found);
    std::string error;
    std::optional<std::string> bytes = read_regular_file_bytes(found.path, error);
    if (!bytes) {
        out.file.problem = error;
        return out;
    }
    // A file named .xml that is not XML (a note, a YAML text, nothing but blanks) would list no
    // device without a word; the docs promise a warning for a file that cannot be indexed.
    if (bytes->find('<') == std::string::npos || document_format(*bytes, found.path) != DocumentFormat::esi_xml) {
        out.file.problem = "not XML (no markup at its start)";
        return out;
    }
    IdentityScan scan = scan_identities(std::move(*bytes));
    if (!scan.ok()) {
        // The scan tokenises only; the reader says precisely where the file breaks.
        const LoadedDocument loaded = load_document_file(found.path);
        out.file.problem = scan.error;
        for (const Diagnostic& d : loaded.diagnostics)
            if (d.severity == Severity::error) {
                out.file.problem = format_location("", d.pos) + ": " + d.message;
                break;
            }
        return out;
    }
    for (ScannedDevice& s : scan.devices) {
        IndexedDevice d;
        d.vendor_id = s.vendor_id;
        d.product_code = s.product_code;
        d.revision_no = s.revision_no;
        d.type = std::move(s.type);
        d.name = std::move(s.name);
        d.vendor_name = std::move(s.vendor_name);
        d.offset = s.offset;
        d.line = s.pos.line;
        d.column = s.pos.column;
        d.ordinal = s.ordinal;
        d.hides = std::move(s.hides);
        out.devices.push_back(std::move(d));
    }
    return out;
}

std::optional<IndexCache> read_cache(const fs::path& file, bool& ignored) {
    ignored = false;
    std::error_code ec;
    if (!fs::exists(file, ec)) return std::nullopt;
    std::string error;
    const std::optional<std::string> bytes = read_regular_file_bytes(file, error);
    std::optional<IndexCache> cache = bytes ? parse_index_cache(*bytes) : std::nullopt;
    ignored = !cache.has_value();
    return cache;
}

}  // namespace

std::optional<fs::path> default_cache_dir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "libesi";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "libesi";
    return std::nullopt;
}

fs::path index_cache_file(const fs::path& cache_dir) { return cache_dir / "esi-index.v3"; }

IndexResult build_library_index(const std::vector<fs::path>& roots, const IndexOptions& options) {
    IndexResult result;
    for (const fs::path& root : roots) result.index.roots.push_back(root.generic_string());
    const std::vector<FoundFile> found = find_files(roots, result.diagnostics);

    IndexCache cache;
    std::optional<fs::path> cache_file;
    if (options.cache_dir) {
        cache_file = index_cache_file(*options.cache_dir);
        if (options.rescan) {
            result.diagnostics.emplace(Severity::info, "net-index-cache",
                                       "the index cache disagreed with a file; every file was indexed anew", cache_file->generic_string(), {});
        } else if (auto read = read_cache(*cache_file, result.stats.cache_ignored)) {
            cache = std::move(*read);
        }
        if (result.stats.cache_ignored)
            result.diagnostics.emplace(Severity::info, "net-index-cache", "the index cache is unreadable or damaged; rebuilt",
                                       cache_file->generic_string(), {});
    }

    bool changed = result.stats.cache_ignored || options.rescan;
    for (const FoundFile& f : found) {
        auto it = cache.find(f.path);
        if (it != cache.end() && it->second.file.size == f.size && it->second.file.mtime_ns == f.mtime_ns &&
            it->second.file.ctime_ns == f.ctime_ns && it->second.file.inode == f.inode) {
            ++result.stats.cached;
        } else {
            CachedFile scanned = scan_file(f);
            ++result.stats.scanned;
            changed = true;
            if (it != cache.end()) it->second = std::move(scanned);
            else it = cache.emplace(f.path, std::move(scanned)).first;
        }
        const CachedFile& entry = it->second;
        const std::size_t file_index = result.index.files.size();
        result.index.files.push_back(entry.file);
        result.index.files.back().root = f.root;
        if (!entry.file.problem.empty())
            result.diagnostics.emplace(Severity::warning, "net-index", "not indexed: " + entry.file.problem, f.path, {});
        for (IndexedDevice d : entry.devices) {
            d.file = file_index;
            result.index.devices.push_back(std::move(d));
        }
    }
    result.stats.files = result.index.files.size();

    if (cache_file && changed) {
        const Diagnostics written = write_file_atomically(*cache_file, format_index_cache(cache));
        result.stats.cache_written = !written.has_errors();
        for (Diagnostic d : written) {
            d.severity = Severity::warning;  // the index is fine; only the next run is slower
            result.diagnostics.add(std::move(d));
        }
    }
    return result;
}

bool index_agrees_with_files(const LibraryIndex& index, const std::vector<const IndexedDevice*>& devices) {
    std::map<std::size_t, std::vector<const IndexedDevice*>> by_file;
    for (const IndexedDevice* d : devices) by_file[d->file].push_back(d);
    for (const auto& [file_number, listed] : by_file) {
        const IndexedFile& file = index.files[file_number];
        FoundFile found;
        std::string why;
        if (!stat_file(file.path, found, why)) return false;
        found.root = file.root;
        const CachedFile now = scan_file(found);
        for (const IndexedDevice* d : listed) {
            if (d->ordinal >= now.devices.size()) return false;
            const IndexedDevice& fresh = now.devices[d->ordinal];
            if (fresh.vendor_id != d->vendor_id || fresh.product_code != d->product_code || fresh.revision_no != d->revision_no ||
                fresh.type != d->type || fresh.offset != d->offset || fresh.hides != d->hides)
                return false;
        }
    }
    return true;
}

}  // namespace esi::net
