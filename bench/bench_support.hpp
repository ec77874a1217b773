#pragma once
// What the file benchmarks share: a best-of-N timer and the largest files of the corpus.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

namespace esi::bench {

using Clock = std::chrono::steady_clock;

inline double milliseconds(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// The fastest of `runs` calls, in milliseconds: on a shared machine the minimum is the run least
// disturbed by other jobs.
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

// The `count` largest *.xml files of ../shared/corpus/esi, largest first; empty without the corpus.
inline std::vector<std::filesystem::path> largest_corpus_files(std::size_t count) {
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

}  // namespace esi::bench
