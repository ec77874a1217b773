#pragma once
// The order in which lint_paths' workers take files, and how many input bytes may be in flight.
//
// A file being linted holds its decoded text, its line index, the pugixml tree and the model:
// about 7 times its size at the peak (Beckhoff's ELM37xx catalogue: 3.9 MB -> 26 MB). Two
// catalogues of that size linted side by side would take esi-lint past its memory target of
// 4 x the largest file + 30 MB (issue 2 §6). So:
// - the input bytes in flight are bounded by a budget (a file larger than the budget may still
//   run, alone);
// - large files (over a quarter of the largest and over 1 MiB) are linted by worker 0 only,
//   largest first; the other workers take the small files, smallest first. Memory a thread
//   frees stays with that thread's malloc arena (glibc keeps one per thread and does not hand
//   freed pages back cheaply), so large files spread over two workers left two arenas of a
//   large file's size: with -j 2 the corpus (largest 3.9 MB) peaked at 50-56 MB with the budget
//   alone, 45 MB with 1.2 MB as the limit for small files and 40 MB with 1 MiB or less.
//   Returning the pages after each large file (malloc_trim) kept 40 MB too, but made the run
//   half again as slow (page faults). Below 1 MiB a file's arena is a few MB, so corpora of
//   smaller files are linted fully in parallel.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <vector>

namespace esi {

class FileQueue {
public:
    // `sizes[i]` is the size of file i in bytes (0 when unknown).
    FileQueue(std::vector<std::uintmax_t> sizes, std::uintmax_t budget);

    // The next file for `worker` (0 ..), waiting while none fits the budget; nullopt when there
    // is nothing left for it.
    [[nodiscard]] std::optional<std::size_t> take(unsigned worker);
    // A taken file is finished: its bytes leave the budget.
    void done(std::size_t file);

    // The budget lint_paths uses: one and a quarter of the largest file (the large catalogues
    // run one at a time, next to small files), at least 1 MiB.
    [[nodiscard]] static std::uintmax_t default_budget(const std::vector<std::uintmax_t>& sizes);

private:
    [[nodiscard]] bool fits(std::size_t file) const;
    [[nodiscard]] bool large(std::size_t file) const { return sizes_[file] > large_limit_; }

    std::vector<std::uintmax_t> sizes_;
    std::uintmax_t budget_;
    std::uintmax_t large_limit_;
    std::uintmax_t in_flight_ = 0;
    std::deque<std::size_t> order_;  // largest first
    std::mutex mutex_;
    std::condition_variable finished_;
};

}  // namespace esi
