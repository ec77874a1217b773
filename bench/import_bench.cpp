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

#include "esi/xml/reader.hpp"
#include "esi/yaml/export.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

template <class F>
double best_of(int runs, F&& f) {
    double best = 1e300;
    for (int i = 0; i < runs; ++i) {
        const auto start = Clock::now();
        f();
        best = std::min(best, milliseconds(Clock::now() - start));
    }
    return best;
}

std::vector<std::filesystem::path> largest_corpus_files(std::size_t count) {
    std::vector<std::pair<std::uintmax_t, std::filesystem::path>> files;
    const std::filesystem::path dir = std::filesystem::path(ESI_SHARED_DIR) / "corpus" / "esi";
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".xml") files.emplace_back(entry.file_size(), entry.path());
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<std::filesystem::path> out;
    for (std::size_t i = 0; i < files.size() && i < count; ++i) out.push_back(files[i].second);
    return out;
}

}  // namespace

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
        const double import_ms = best_of(2, [&] { imported = esi::export_device_source(*document); });
        esi::ImportOptions explicit_options;
        explicit_options.omit_derived = false;
        const double explicit_ms = best_of(3, [&] { (void)esi::export_device_source(*document, explicit_options); });
        const double mb = static_cast<double>(bytes->size()) / 1e6;
        std::printf("%-45.45s %7.2f %8zu %9.1f %9.1f %9.2f %9.1f %9.1f\n", path.filename().string().c_str(), mb, imported.devices, read_ms,
                    import_ms, mb / (import_ms / 1e3), explicit_ms, mb / (explicit_ms / 1e3));
    }
    return 0;
}
