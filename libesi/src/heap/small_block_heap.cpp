// The small-block heap (small_block_heap.hpp): per-thread free lists over pages of one
// size class, and the replaced global operator new and delete that use them.

#include "heap/small_block_heap.hpp"

#include <pthread.h>
#include <sys/mman.h>
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <mutex>
#include <new>

#include "core/sanitizers.hpp"

// A sanitizer must see every allocation: the heap steps aside (small_block_heap.hpp).
#define ESI_SMALL_BLOCK_HEAP (!ESI_SANITIZER)

namespace esi::heap {

namespace {

constexpr std::size_t class_count = max_small_block / small_block_step;
constexpr unsigned page_shift = 16;
static_assert(small_block_page == std::size_t{1} << page_shift);
constexpr std::size_t full_reservation = std::size_t{4} << 30;
constexpr std::size_t max_pages = full_reservation / small_block_page;

// A free block holds the link to the next free block of its class.
struct FreeBlock {
    FreeBlock* next;
};

// One thread's lists and the page each class is carving blocks from. Zero-initialised and
// trivially destructible, so reaching it costs no guard.
struct ThreadCache {
    FreeBlock* free[class_count];
    char* carve[class_count];
    char* carve_end[class_count];
    bool registered;  // for the hand-over when the thread ends
};
thread_local ThreadCache cache;

// The reservation. Until it is made (or when it cannot be), `reserved` is 0 and the ownership
// test false for every block. Written once; a thread that frees a small block received it from
// the thread that allocated it, after the reservation, so relaxed loads see the values.
std::atomic<std::uintptr_t> base{0};
std::atomic<std::size_t> reserved{0};
std::size_t page_limit = 0;
std::atomic<std::size_t> pages_taken{0};
unsigned char page_class[max_pages];  // the size class of each page taken
static_assert(class_count <= 256, "a page's class is one byte");
std::once_flag reservation_made;

// Blocks of threads that ended, by class, for the next thread that needs a page.
std::mutex orphan_mutex;
FreeBlock* orphans[class_count];
std::atomic<bool> have_orphans{false};
pthread_key_t thread_end_key;
std::once_flag thread_end_key_made;

constexpr std::size_t block_size(std::size_t c) { return (c + 1) * small_block_step; }

void reserve() {
    rlimit limit{};
    std::optional<std::uint64_t> address_space_limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) address_space_limit = limit.rlim_cur;
    const std::size_t size = reservation_for(address_space_limit);
    if (size == 0) return;
    // Only the pages blocks are carved from are ever touched, so only they use memory.
    void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) return;
    page_limit = size / small_block_page;
    base.store(reinterpret_cast<std::uintptr_t>(p), std::memory_order_relaxed);
    reserved.store(size, std::memory_order_release);
}

// Hands every list of the thread to the orphans. Runs when the thread ends. What is left of the
// pages it was carving stays unused: it was never touched, so it takes no memory.
void hand_over(void*) {
    ThreadCache& c = cache;
    const std::lock_guard lock(orphan_mutex);
    for (std::size_t k = 0; k < class_count; ++k) {
        c.carve[k] = c.carve_end[k] = nullptr;
        FreeBlock* list = c.free[k];
        if (!list) continue;
        FreeBlock* last = list;
        while (last->next) last = last->next;
        last->next = orphans[k];
        orphans[k] = list;
        c.free[k] = nullptr;
        have_orphans.store(true, std::memory_order_release);
    }
    c.registered = false;
}

void register_thread() {
    std::call_once(thread_end_key_made, [] {
        if (pthread_key_create(&thread_end_key, hand_over) != 0) thread_end_key = pthread_key_t{};
    });
    // The value only has to be non-null for the destructor to run.
    pthread_setspecific(thread_end_key, &cache);
    cache.registered = true;
}

// The slow path of an allocation of class k: the orphans of that class, else a new page.
[[gnu::noinline]] void* refill(std::size_t k) {
    std::call_once(reservation_made, reserve);
    if (reserved.load(std::memory_order_acquire) == 0) return nullptr;
    if (!cache.registered) register_thread();
    if (have_orphans.load(std::memory_order_acquire)) {
        const std::lock_guard lock(orphan_mutex);
        if (FreeBlock* list = orphans[k]) {
            orphans[k] = nullptr;
            cache.free[k] = list->next;
            return list;
        }
    }
    const std::size_t page = pages_taken.fetch_add(1, std::memory_order_relaxed);
    if (page >= page_limit) return nullptr;  // the reservation is used up: malloc from now on
    page_class[page] = static_cast<unsigned char>(k);
    char* start = reinterpret_cast<char*>(base.load(std::memory_order_relaxed) + (page << page_shift));
    cache.carve[k] = start + block_size(k);
    cache.carve_end[k] = start + small_block_page - small_block_page % block_size(k);
    return start;
}

inline std::uintptr_t offset_of(const void* p) { return reinterpret_cast<std::uintptr_t>(p) - base.load(std::memory_order_relaxed); }
inline bool owned(const void* p) { return offset_of(p) < reserved.load(std::memory_order_relaxed); }

inline void* allocate_small(std::size_t n) {
    const std::size_t k = n == 0 ? 0 : (n - 1) / small_block_step;
    if (FreeBlock* b = cache.free[k]) {
        cache.free[k] = b->next;
        return b;
    }
    if (char* p = cache.carve[k]; p != cache.carve_end[k]) {
        cache.carve[k] = p + block_size(k);
        return p;
    }
    return refill(k);
}

[[gnu::always_inline, maybe_unused]] inline void release(void* p) {
    if (owned(p)) {
        const std::size_t k = page_class[offset_of(p) >> page_shift];
        auto* b = static_cast<FreeBlock*>(p);
        b->next = cache.free[k];
        cache.free[k] = b;
        return;
    }
    std::free(p);
}

void* allocate(std::size_t n) {
    if (n <= max_small_block)
        if (void* p = allocate_small(n)) return p;
    for (;;) {
        if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
        const std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

[[maybe_unused]] void* allocate_or_null(std::size_t n) noexcept {
    try {
        return allocate(n);
    } catch (...) {
        return nullptr;
    }
}

}  // namespace

std::size_t reservation_for(std::optional<std::uint64_t> address_space_limit) {
    if (!ESI_SMALL_BLOCK_HEAP || address_space_limit) return 0;
    return full_reservation;
}

bool small_block_heap_active() {
    std::call_once(reservation_made, reserve);
    return reserved.load(std::memory_order_acquire) != 0;
}

bool is_small_block(const void* p) { return owned(p); }

std::size_t small_block_pages() { return std::min(pages_taken.load(std::memory_order_relaxed), page_limit); }

}  // namespace esi::heap

#if ESI_SMALL_BLOCK_HEAP
// The replaceable allocation functions ([new.delete]). The aligned forms are not replaced: the
// library's own pair (aligned_alloc and free) serves them.
void* operator new(std::size_t n) { return esi::heap::allocate(n); }
void* operator new[](std::size_t n) { return esi::heap::allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return esi::heap::allocate_or_null(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return esi::heap::allocate_or_null(n); }
void operator delete(void* p) noexcept { esi::heap::release(p); }
void operator delete[](void* p) noexcept { esi::heap::release(p); }
void operator delete(void* p, std::size_t) noexcept { esi::heap::release(p); }
void operator delete[](void* p, std::size_t) noexcept { esi::heap::release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { esi::heap::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { esi::heap::release(p); }
#endif
