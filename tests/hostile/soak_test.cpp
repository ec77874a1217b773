// Soak (issue 6 §3): lint the whole corpus 50 times in one process through the library API and
// check that memory does not grow: a leak or an ever-growing cache in the reader, the rules or
// the report shows as resident memory that keeps rising from round to round.

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <thread>

#include "esi/lint/lint.hpp"
#include "esi/report/lint_output.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

// Resident set size of this process now, in KiB (/proc/self/statm, second field, in pages).
long resident_kb() {
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
    long after_round_5 = 0;
    long after_round_50 = 0;
    for (int round = 1; round <= 50; ++round) {
        const esi::LintReport report = esi::lint_paths({esi::test::corpus_esi_dir()}, options);
        const std::string json = esi::render_json(report);
        if (round == 1) {
            first_json = json;
            ASSERT_GT(report.files.size(), 50u);
        } else {
            ASSERT_EQ(json, first_json) << "round " << round << " reports differently";
        }
        if (round == 5) after_round_5 = resident_kb();
        if (round == 50) after_round_50 = resident_kb();
    }
    // Tolerance: 10 % of the round-5 figure plus 16 MiB, for allocator arenas of the worker
    // threads settling; a leak of one corpus round's documents would be far more.
    const long tolerance = after_round_5 / 10 + 16 * 1024;
    std::cout << "[          ] resident memory after round 5: " << after_round_5 << " KiB, after round 50: "
              << after_round_50 << " KiB (tolerance " << tolerance << " KiB)\n";
    EXPECT_LE(after_round_50, after_round_5 + tolerance);
}
