// Soak (issue 6 §3): lint the whole corpus 50 times in one process through the library API and
// check that memory does not grow: a leak or an ever-growing cache in the reader, the rules or
// the report shows as resident memory that keeps rising from round to round.

#include <gtest/gtest.h>

#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <fstream>
#include <thread>

#include "esi/lint/lint.hpp"
#include "esi/report/lint_output.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

// Resident set size of this process now, in KiB (/proc/self/statm, second field, in pages).
// Free memory is first handed back to the system: glibc keeps freed pages of each worker
// thread's arena resident, and how many it keeps varies from round to round with the order in
// which the threads happen to free; that is not growth of what the library holds.
long resident_kb() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
    std::ifstream statm("/proc/self/statm");
    long size = 0, resident = 0;
    statm >> size >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

}  // namespace

TEST(Soak, LintingTheCorpusFiftyTimesDoesNotGrowMemory) {
    ESI_REQUIRE_CORPUS();
    if (esi::test::memory_scale() > 1)
        GTEST_SKIP() << "AddressSanitizer keeps freed memory in quarantine, so resident memory says nothing about "
                        "leaks there; the sanitizer build's leak checker covers them";
    esi::LintOptions options;  // jobs = 0: all cores
    std::string first_json;
    // A leak grows from round to round; the allocator's keeping of pages varies up and down (with
    // the order in which the worker threads free, more so on a loaded machine). So the early
    // figure is the highest of rounds 4-8 and the late one the lowest of rounds 46-50: one noisy
    // round late in the run does not fail the test, a steady growth still does.
    long early = 0;
    long late = -1;
    for (int round = 1; round <= 50; ++round) {
        const esi::LintReport report = esi::lint_paths({esi::test::corpus_esi_dir()}, options);
        const std::string json = esi::render_json(report);
        if (round == 1) {
            first_json = json;
            ASSERT_GT(report.files.size(), 50u);
        } else {
            ASSERT_EQ(json, first_json) << "round " << round << " reports differently";
        }
        if (round >= 4 && round <= 8) early = std::max(early, resident_kb());
        if (round >= 46) late = late < 0 ? resident_kb() : std::min(late, resident_kb());
    }
    // Tolerance: 10 % of the early figure plus 8 MiB, for allocator bookkeeping of the worker
    // threads (about 10 MiB at the usual 15-20 MiB); a leak of 300 KiB per round (38 rounds
    // between the two windows) already exceeds it, and one corpus round's documents are far more.
    const long tolerance = early / 10 + 8 * 1024;
    std::cout << "[          ] resident memory, highest of rounds 4-8: " << early << " KiB, lowest of rounds 46-50: " << late
              << " KiB (tolerance " << tolerance << " KiB)\n";
    EXPECT_LE(late, early + tolerance);
}
