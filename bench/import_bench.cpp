// esi-gen --import speed on the largest corpus catalogues: for each file, the time to read it
// (for scale), to import it with derivation checks (every device is written, loaded and compared
// once or more, docs/yaml-import.md) and without them (everything explicit), with input MB/s.
// Usage: import_bench [FILE...]   (default: the 3 largest files of ../shared/corpus/esi)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "esi/import/import.hpp"
#include "esi/io/read_file.hpp"
#include "esi/xml/reader.hpp"

using esi::bench::best_of;
using esi::bench::largest_corpus_files;

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
    if (files.empty()) files = largest_corpus_files(3);
    if (files.empty()) {
        std::printf("no input files (pass some, or provide ../shared/corpus/esi)\n");
        return 0;
    }
    std::printf("%-45s %7s %8s %9s %9s %9s %9s %9s\n", "file", "in MB", "devices", "read ms", "import ms", "MB/s", "explicit", "MB/s");
    for (const auto& path : files) {
        std::string error;
        const auto bytes = esi::read_file_bytes(path, error);
        if (!bytes) continue;
        esi::ReadOptions read_options;
        read_options.keep_source = false;
        std::optional<esi::EsiDocument> document;
        const double read_ms = best_of(3, [&] { document = esi::read_esi(*bytes, path.string(), read_options).document; });
        if (!document) continue;
        esi::ImportResult imported;
        const double import_ms = best_of(2, [&] { imported = esi::import_device_source(*document); });
        esi::ImportOptions explicit_options;
        explicit_options.omit_derived = false;
        const double explicit_ms = best_of(3, [&] { (void)esi::import_device_source(*document, explicit_options); });
        const double mb = static_cast<double>(bytes->size()) / 1e6;
        std::printf("%-45.45s %7.2f %8zu %9.1f %9.1f %9.2f %9.1f %9.1f\n", path.filename().string().c_str(), mb, imported.devices, read_ms,
                    import_ms, mb / (import_ms / 1e3), explicit_ms, mb / (explicit_ms / 1e3));
    }
    return 0;
}
