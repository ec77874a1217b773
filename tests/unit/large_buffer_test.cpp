// Large buffers (esi/large_buffer.hpp): every size holds what is written to it, reallocating keeps
// the bytes asked for across the heap/mapping boundary, a freed mapping serves the same thread's
// next buffer, and none outlives its thread or the length limit of the cache. Whether memory is
// still mapped is asked of the system (mincore fails with ENOMEM on an address no mapping covers).

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <thread>
#include <vector>

#include "esi/large_buffer.hpp"

namespace {

constexpr std::size_t mib = std::size_t{1} << 20;

// Writes a byte every 4093 (a prime: each lands at another place in its page) and the last one.
void fill(void* p, std::size_t bytes, unsigned char seed) {
    auto* b = static_cast<unsigned char*>(p);
    for (std::size_t i = 0; i + 1 < bytes; i += 4093) b[i] = static_cast<unsigned char>(seed + i);
    b[bytes - 1] = static_cast<unsigned char>(seed ^ 0x5a);
}

// Whether the first `kept` bytes still hold what fill(p, filled, seed) wrote there.
bool holds(const void* p, std::size_t kept, std::size_t filled, unsigned char seed) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i + 1 < filled && i < kept; i += 4093)
        if (b[i] != static_cast<unsigned char>(seed + i)) return false;
    return kept < filled || b[filled - 1] == static_cast<unsigned char>(seed ^ 0x5a);
}

bool mapped(const void* p) {
    const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    unsigned char resident = 0;
    void* start = reinterpret_cast<void*>(reinterpret_cast<std::uintptr_t>(p) / page * page);
    return ::mincore(start, 1, &resident) == 0 || errno != ENOMEM;
}

TEST(LargeBuffer, EverySizeHoldsWhatIsWrittenAndIsAlignedForAnyType) {
    for (const std::size_t bytes : {std::size_t{1}, std::size_t{1000}, esi::large_buffer_from_bytes - 1,
                                    esi::large_buffer_from_bytes, mib, 3 * mib + 5, 9 * mib}) {
        void* p = esi::allocate_large_buffer(bytes);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % alignof(std::max_align_t), 0u) << bytes;
        fill(p, bytes, 7);
        EXPECT_TRUE(holds(p, bytes, bytes, 7)) << bytes;
        esi::free_large_buffer(p, bytes);
    }
}

TEST(LargeBuffer, ReallocatingKeepsTheBytesAskedForAcrossEveryBoundary) {
    // Heap block -> mapping -> longer mapping -> one past the cache's limit -> heap block again.
    const std::size_t steps[] = {100000, 300000, 5 * mib, 20 * mib, 60000};
    std::size_t old_bytes = 0;
    std::size_t filled = 0;
    void* p = nullptr;
    for (const std::size_t bytes : steps) {
        p = esi::reallocate_large_buffer(p, old_bytes, bytes, filled);
        ASSERT_NE(p, nullptr);
        const std::size_t kept = std::min(filled, bytes);
        if (kept) {
            EXPECT_TRUE(holds(p, kept, filled, 3)) << old_bytes << " -> " << bytes;
        }
        fill(p, bytes, 3);
        filled = bytes;
        old_bytes = bytes;
    }
    esi::free_large_buffer(p, old_bytes);
}

TEST(LargeBuffer, ReallocatingWithinTheMappingKeepsItsAddress) {
    if (!esi::large_buffers_are_mappings()) GTEST_SKIP() << "a sanitizer's build: large buffers are heap blocks";
    void* p = esi::allocate_large_buffer(mib / 2);
    fill(p, mib / 2, 9);
    // Both sizes fit the same 1 MiB mapping.
    EXPECT_EQ(esi::reallocate_large_buffer(p, mib / 2, mib / 2 + 1000, mib / 2), p);
    EXPECT_TRUE(holds(p, mib / 2, mib / 2, 9));
    esi::free_large_buffer(p, mib / 2 + 1000);
}

TEST(LargeBuffer, AFreedMappingServesTheThreadsNextBufferWithItsPages) {
    if (!esi::large_buffers_are_mappings()) GTEST_SKIP() << "a sanitizer's build: large buffers are heap blocks";
    // 7 MiB: longer than what the tests before left in this thread's cache, so the smallest kept
    // mapping long enough is this one.
    void* first = esi::allocate_large_buffer(7 * mib);
    fill(first, 7 * mib, 6);
    esi::free_large_buffer(first, 7 * mib);
    void* second = esi::allocate_large_buffer(7 * mib - 4096);
    EXPECT_EQ(second, first);
    esi::free_large_buffer(second, 7 * mib - 4096);
}

TEST(LargeBuffer, AThreadsKeptMappingsAreUnmappedWhenItEnds) {
    if (!esi::large_buffers_are_mappings()) GTEST_SKIP() << "a sanitizer's build: large buffers are heap blocks";
    std::vector<void*> kept;
    std::thread worker([&] {
        const std::size_t sizes[] = {mib, 2 * mib, 3 * mib};
        for (const std::size_t bytes : sizes) {
            kept.push_back(esi::allocate_large_buffer(bytes));
            fill(kept.back(), bytes, 1);
        }
        for (std::size_t i = 0; i < kept.size(); ++i) esi::free_large_buffer(kept[i], sizes[i]);
        for (void* p : kept) EXPECT_TRUE(mapped(p)) << "kept for the thread's next buffer";
    });
    worker.join();
    for (void* p : kept) EXPECT_FALSE(mapped(p)) << "still mapped after its thread ended";
}

TEST(LargeBuffer, AMappingLongerThanTheCacheKeepsIsUnmappedWhenFreed) {
    if (!esi::large_buffers_are_mappings()) GTEST_SKIP() << "a sanitizer's build: large buffers are heap blocks";
    void* p = esi::allocate_large_buffer(12 * mib);
    fill(p, 12 * mib, 2);
    esi::free_large_buffer(p, 12 * mib);
    EXPECT_FALSE(mapped(p));
}

TEST(LargeBuffer, ABufferFreedByAnotherThreadIsKeptThere) {
    void* p = esi::allocate_large_buffer(mib);
    fill(p, mib, 4);
    std::thread other([&] {
        EXPECT_TRUE(holds(p, mib, mib, 4));
        esi::free_large_buffer(p, mib);
    });
    other.join();
    if (esi::large_buffers_are_mappings()) {
        EXPECT_FALSE(mapped(p)) << "kept by the thread that freed it, which ended";
    }
}

TEST(LargeBuffer, AVectorOverThemGrowsWithoutZeroingAndKeepsItsElements) {
    std::vector<std::uint32_t, esi::LargeBufferAllocator<std::uint32_t>> list;
    for (std::uint32_t i = 0; i < 500000; ++i) list.push_back(i * 3);
    list.resize(600000);
    for (std::uint32_t i = 0; i < 500000; i += 997) ASSERT_EQ(list[i], i * 3);
    EXPECT_EQ(list.size(), 600000u);
}

}  // namespace
