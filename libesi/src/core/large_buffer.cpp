// Large buffers (large_buffer.hpp): mappings with a small header that holds their length, and a
// per-thread cache of the ones freed, unmapped when the thread ends.

#include "esi/large_buffer.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <new>

#include "core/sanitizers.hpp"

// Under a sanitizer every buffer is a heap block, so that reads and writes past its end are caught.
#define ESI_LARGE_BUFFER_MAPPINGS (!ESI_SANITIZER)

namespace esi {

namespace {

// The header before the buffer: the mapping's length. 64 bytes keep the buffer aligned to a cache
// line (and to any type).
constexpr std::size_t header_bytes = 64;
// Mappings are made in steps of this, so that buffers of nearly the same size share them.
constexpr std::size_t mapping_step = std::size_t{1} << 20;
// How many freed mappings a thread keeps: a file's buffers (bytes, nodes, attributes, line index,
// and the smaller array a growing one left) with room to spare.
constexpr std::size_t cached_per_thread = 8;
// Longer mappings (a big catalogue's node array) are unmapped when freed: kept, their pages would
// stay resident through the rest of the run, next to the model read from the file
// (docs/performance.md, peak memory).
constexpr std::size_t longest_cached = std::size_t{8} << 20;

std::size_t& length_of(void* mapping) { return *static_cast<std::size_t*>(mapping); }

// `mapping` lengthened to `length` bytes (in place, or moved by the system without copying);
// null, and `mapping` unchanged, when the system refuses.
void* lengthened(void* mapping, std::size_t length) {
    void* moved = ::mremap(mapping, length_of(mapping), length, MREMAP_MAYMOVE);
    if (moved == MAP_FAILED) return nullptr;
    length_of(moved) = length;
    return moved;
}

// One thread's freed mappings. Trivially destructible: a buffer freed after the thread's
// clean-up ran (an object of static storage, destroyed after the main thread's thread_local
// objects) finds the cache closed and is unmapped at once.
struct MappingCache {
    std::array<void*, cached_per_thread> mappings;
    std::size_t count;
    bool closed;

    // A kept mapping for `length` bytes, taken out of the cache: the smallest that is long enough,
    // else the longest, lengthened (its pages, touched by an earlier file, are used again rather
    // than left resident next to new ones); null if the cache is empty or lengthening fails.
    void* take(std::size_t length) {
        if (count == 0) return nullptr;
        std::size_t fit = count;
        std::size_t longest = 0;
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t l = length_of(mappings[i]);
            if (l >= length && (fit == count || l < length_of(mappings[fit]))) fit = i;
            if (l > length_of(mappings[longest])) longest = i;
        }
        const std::size_t chosen = fit < count ? fit : longest;
        void* mapping = mappings[chosen];
        mappings[chosen] = mappings[--count];
        if (length_of(mapping) >= length) return mapping;
        void* moved = lengthened(mapping, length);
        if (!moved) ::munmap(mapping, length_of(mapping));
        return moved;
    }

    // Keeps a freed mapping; when the cache is full, the smallest of them all is unmapped (the
    // bigger ones serve more requests).
    void keep(void* mapping);

    void close() {
        for (std::size_t i = 0; i < count; ++i) ::munmap(mappings[i], length_of(mappings[i]));
        count = 0;
        closed = true;
    }
};

thread_local MappingCache cache;

// Unmaps the cache when the thread ends; made on the thread's first keep.
struct CacheCloser {
    CacheCloser() = default;
    CacheCloser(const CacheCloser&) = delete;
    CacheCloser& operator=(const CacheCloser&) = delete;
    ~CacheCloser() { cache.close(); }
};

void MappingCache::keep(void* mapping) {
    static thread_local CacheCloser closer;
    if (closed || length_of(mapping) > longest_cached) {
        ::munmap(mapping, length_of(mapping));
        return;
    }
    if (count < cached_per_thread) {
        mappings[count++] = mapping;
        return;
    }
    std::size_t smallest = 0;
    for (std::size_t i = 1; i < count; ++i)
        if (length_of(mappings[i]) < length_of(mappings[smallest])) smallest = i;
    if (length_of(mapping) > length_of(mappings[smallest])) std::swap(mapping, mappings[smallest]);
    ::munmap(mapping, length_of(mapping));
}

bool is_mapping(std::size_t bytes) { return ESI_LARGE_BUFFER_MAPPINGS && bytes >= large_buffer_from_bytes; }

// The length of the mapping for a buffer of `bytes`.
std::size_t mapping_length(std::size_t bytes) {
    if (bytes > SIZE_MAX - header_bytes - mapping_step) throw std::bad_alloc();
    return (bytes + header_bytes + mapping_step - 1) / mapping_step * mapping_step;
}

}  // namespace

bool large_buffers_are_mappings() noexcept { return ESI_LARGE_BUFFER_MAPPINGS; }

void* allocate_large_buffer(std::size_t bytes) {
    if (!is_mapping(bytes)) return ::operator new(bytes);
    const std::size_t length = mapping_length(bytes);
    void* mapping = cache.take(length);
    if (!mapping) {
        mapping = ::mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (mapping == MAP_FAILED) throw std::bad_alloc();
        length_of(mapping) = length;
    }
    return static_cast<char*>(mapping) + header_bytes;
}

void free_large_buffer(void* p, std::size_t bytes) noexcept {
    if (!p) return;
    if (!is_mapping(bytes)) {
        ::operator delete(p);
        return;
    }
    cache.keep(static_cast<char*>(p) - header_bytes);
}

void* reallocate_large_buffer(void* p, std::size_t old_bytes, std::size_t new_bytes, std::size_t keep_bytes) {
    if (p && is_mapping(old_bytes) && is_mapping(new_bytes)) {
        void* mapping = static_cast<char*>(p) - header_bytes;
        const std::size_t length = mapping_length(new_bytes);
        if (length <= length_of(mapping)) return p;
        void* moved = lengthened(mapping, length);
        if (!moved) throw std::bad_alloc();
        return static_cast<char*>(moved) + header_bytes;
    }
    void* bigger = allocate_large_buffer(new_bytes);
    if (p) {
        std::memcpy(bigger, p, std::min(keep_bytes, std::min(old_bytes, new_bytes)));
        free_large_buffer(p, old_bytes);
    }
    return bigger;
}

}  // namespace esi
