// The small-block heap that esi-lint links (libesi/src/heap): this test program links it too, so
// every operator new here goes through it. The tests skip in builds where it steps aside
// (AddressSanitizer), saying so.

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/sanitizers.hpp"
#include "heap/small_block_heap.hpp"

namespace {

using esi::heap::is_small_block;
using esi::heap::max_small_block;
using esi::heap::small_block_heap_active;
using esi::heap::small_block_pages;

#define SKIP_WITHOUT_HEAP()                                                                                   \
    if (!small_block_heap_active())                                                                           \
    GTEST_SKIP() << "the small-block heap steps aside in this build or process (sanitizers, RLIMIT_AS); "  \
                    "every allocation comes from malloc"

char* block(std::size_t n) { return static_cast<char*>(::operator new(n)); }
void give_back(char* p) { ::operator delete(p); }

TEST(SmallBlockHeap, EverySizeGetsDistinctAlignedBlocksThatKeepTheirContent) {
    SKIP_WITHOUT_HEAP();
    struct Held {
        char* p;
        std::size_t n;
    };
    std::vector<Held> held;
    held.reserve(max_small_block * 40);
    for (int round = 0; round < 40; ++round)
        for (std::size_t n = 1; n <= max_small_block; ++n) {
            char* p = block(n);
            ASSERT_TRUE(is_small_block(p)) << n;
            ASSERT_EQ(reinterpret_cast<std::uintptr_t>(p) % 16, 0u) << n;
            std::memset(p, static_cast<int>((n + static_cast<std::size_t>(round)) & 0xFF), n);
            held.push_back({p, n});
        }
    // Every block still holds what was written into it: no two overlap.
    std::set<char*> starts;
    for (std::size_t i = 0; i < held.size(); ++i) {
        const auto [p, n] = held[i];
        const int round = static_cast<int>(i / max_small_block);
        for (std::size_t j = 0; j < n; ++j)
            ASSERT_EQ(static_cast<unsigned char>(p[j]), (n + static_cast<std::size_t>(round)) & 0xFF) << "block of " << n;
        starts.insert(p);
    }
    EXPECT_EQ(starts.size(), held.size());
    for (const auto& h : held) give_back(h.p);
}

TEST(SmallBlockHeap, LargerBlocksAndNothingComeFromMalloc) {
    SKIP_WITHOUT_HEAP();
    char* big = block(max_small_block + 1);
    EXPECT_FALSE(is_small_block(big));
    char* c_block = static_cast<char*>(std::malloc(24));
    EXPECT_FALSE(is_small_block(c_block));
    std::free(c_block);
    give_back(big);
    EXPECT_FALSE(is_small_block(nullptr));
    ::operator delete(nullptr);  // a no-op, as for every operator delete

    char* zero = block(0);  // a distinct block, as the standard asks of new of zero bytes
    char* other = block(0);
    EXPECT_NE(zero, other);
    give_back(zero);
    give_back(other);
}

TEST(SmallBlockHeap, AFreedBlockIsTheNextOfItsSize) {
    SKIP_WITHOUT_HEAP();
    char* a = block(40);
    give_back(a);
    char* b = block(33);  // 33..48 bytes share a size class
    EXPECT_EQ(a, b);
    give_back(b);
}

TEST(SmallBlockHeap, AStringModelBuiltAndFreedTwiceTakesNoNewPages) {
    SKIP_WITHOUT_HEAP();
    const auto build = [] {
        std::vector<std::unique_ptr<std::string>> strings;
        for (int i = 0; i < 20000; ++i)
            strings.push_back(std::make_unique<std::string>("a name longer than fifteen characters #" + std::to_string(i)));
        return strings;
    };
    build();
    const std::size_t pages = small_block_pages();
    for (int i = 0; i < 3; ++i) build();
    EXPECT_EQ(small_block_pages(), pages);
}

TEST(SmallBlockHeap, BlocksFreedOnAnotherThreadServeThatThread) {
    SKIP_WITHOUT_HEAP();
    std::vector<char*> made;
    for (int i = 0; i < 5000; ++i) made.push_back(block(96));
    const std::set<char*> made_set(made.begin(), made.end());
    std::vector<char*> reused;
    std::thread([&] {
        for (char* p : made) give_back(p);
        for (int i = 0; i < 5000; ++i) reused.push_back(block(96));
        for (char* p : reused) give_back(p);
    }).join();
    std::size_t same = 0;
    for (char* p : reused) same += made_set.count(p);
    EXPECT_EQ(same, reused.size());
}

TEST(SmallBlockHeap, AThreadThatEndsHandsItsBlocksToTheNext) {
    SKIP_WITHOUT_HEAP();
    const auto churn = [] {
        std::vector<char*> held;
        for (int i = 0; i < 30000; ++i) held.push_back(block(200));
        for (char* p : held) give_back(p);
    };
    std::thread(churn).join();
    const std::size_t pages = small_block_pages();
    for (int i = 0; i < 4; ++i) std::thread(churn).join();
    EXPECT_EQ(small_block_pages(), pages) << "each new thread should take over the blocks of the one before";
}

TEST(SmallBlockHeap, ManyThreadsAllocatingAndFreeingAcrossKeepEveryBlockIntact) {
    SKIP_WITHOUT_HEAP();
    constexpr int threads = 4;
    constexpr int per_thread = 20000;
    std::vector<std::vector<char*>> made(threads);
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            for (int i = 0; i < per_thread; ++i) {
                const std::size_t n = 1 + static_cast<std::size_t>((i * 37 + t) % static_cast<int>(max_small_block));
                char* p = block(n);
                std::memset(p, t + 1, n);
                made[static_cast<std::size_t>(t)].push_back(p);
            }
        });
    for (auto& w : workers) w.join();
    workers.clear();
    // Each thread checks and frees the blocks of the next one.
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            const int owner = (t + 1) % threads;
            int i = 0;
            for (char* p : made[static_cast<std::size_t>(owner)]) {
                const std::size_t n = 1 + static_cast<std::size_t>((i++ * 37 + owner) % static_cast<int>(max_small_block));
                for (std::size_t j = 0; j < n; ++j)
                    if (p[j] != owner + 1) {
                        ADD_FAILURE() << "block of " << n << " overwritten";
                        return;
                    }
                give_back(p);
            }
        });
    for (auto& w : workers) w.join();
}

// AddressSanitizer's own operator new ends the process on an impossible size (unless told
// allocator_may_return_null), where ours throws.
constexpr bool sanitizer_build = ESI_SANITIZER;

TEST(SmallBlockHeap, AnImpossibleSizeThrowsBadAlloc) {
    if (sanitizer_build) GTEST_SKIP() << "a sanitizer's operator new aborts on an impossible size instead of throwing";
    EXPECT_THROW((void)::operator new(std::size_t{1} << 62), std::bad_alloc);
    EXPECT_EQ(::operator new(std::size_t{1} << 62, std::nothrow), nullptr);
}

TEST(SmallBlockHeap, NoReservationUnderAnAddressSpaceLimit) {
    EXPECT_EQ(esi::heap::reservation_for(std::uint64_t{2} << 30), 0u);
    if (small_block_heap_active()) {
        EXPECT_EQ(esi::heap::reservation_for(std::nullopt), std::size_t{4} << 30);
    }
}

// Started again by the next test under RLIMIT_AS, this program only answers whether the heap
// stepped aside (exit status 0) and ends before the tests run.
[[maybe_unused]] const bool answered_under_limit = [] {
    if (!std::getenv("ESI_HEAP_TEST_UNDER_LIMIT")) return false;
    char* p = block(32);
    const bool malloc_only = !small_block_heap_active() && !is_small_block(p);
    give_back(p);
    _exit(malloc_only ? 0 : 1);
}();

TEST(SmallBlockHeap, UnderAnAddressSpaceLimitEverythingComesFromMalloc) {
    SKIP_WITHOUT_HEAP();
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const rlimit limit{std::uint64_t{3} << 30, std::uint64_t{3} << 30};
        setrlimit(RLIMIT_AS, &limit);
        setenv("ESI_HEAP_TEST_UNDER_LIMIT", "1", 1);
        const char* argv[] = {"heap_tests", nullptr};
        execv("/proc/self/exe", const_cast<char* const*>(argv));
        _exit(127);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: the heap served a small block under the limit; 127: the program did not start";
}

}  // namespace
