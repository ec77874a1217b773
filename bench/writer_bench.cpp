// ESI writer speed on the largest corpus files: for each, the time to read it (for scale) and
// the time to write the model back (best of several runs), with the output size and rate.
// Usage: writer_bench [FILE...]   (default: the 5 largest files of ../shared/corpus/esi)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "esi/io/read_file.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"

using esi::bench::best_of;
using esi::bench::largest_corpus_files;

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
    if (files.empty()) files = largest_corpus_files(5);
    if (files.empty()) {
        std::printf("no input files (pass some, or provide ../shared/corpus/esi)\n");
        return 0;
    }
    std::printf("%-55s %9s %9s %9s %9s\n", "file", "in MB", "read ms", "write ms", "MB/s out");
    for (const auto& path : files) {
        std::string error;
        const auto bytes = esi::read_file_bytes(path, error);
        if (!bytes) continue;
        esi::ReadOptions options;
        options.keep_source = false;
        std::optional<esi::EsiDocument> document;
        const double read_ms = best_of(3, [&] { document = esi::read_esi(*bytes, path.string(), options).document; });
        if (!document) continue;
        std::string written;
        const double write_ms = best_of(10, [&] { written = esi::write_esi(*document); });
        std::printf("%-55.55s %9.2f %9.2f %9.2f %9.0f\n", path.filename().string().c_str(), static_cast<double>(bytes->size()) / 1e6,
                    read_ms, write_ms, static_cast<double>(written.size()) / 1e6 / (write_ms / 1e3));
    }
    return 0;
}
