#pragma once
// Memory for the big buffers that live while one file is read and go with it: the file's bytes,
// the parser's node and attribute arrays, the line index. From large_buffer_from_bytes on they are
// mappings kept in a small cache of the thread that frees them, and the cache is unmapped when
// the thread ends; smaller ones are ordinary heap blocks.
//
// Why not the heap: glibc raises its mmap and trim thresholds up to the size of the biggest block
// it mapped and freed, after which blocks of that size come from the per-thread heaps, whose free
// top stays resident after the threads of a lint run have ended (malloc_trim does not give it
// back). A process that lints again and again (the soak test, an editor's server) then holds
// some tens of MiB more or less from run to run, depending on which thread happened to free what.
// The cache keeps what the heap gave, pages already touched for the next file of the same thread,
// without that: its pages go with the thread. A growing array is lengthened in place
// (reallocate_large_buffer), so the halves it outgrew are not kept either.

#include <cstddef>
#include <memory>
#include <utility>

namespace esi {

inline constexpr std::size_t large_buffer_from_bytes = std::size_t{256} << 10;

// `bytes` of memory aligned for any type; throws std::bad_alloc.
[[nodiscard]] void* allocate_large_buffer(std::size_t bytes);
// Gives back what allocate_large_buffer(bytes) returned, `bytes` the same.
void free_large_buffer(void* p, std::size_t bytes) noexcept;
// A buffer of `new_bytes` that holds the first `keep_bytes` of `p` (a buffer of `old_bytes`, or
// null); `p` is gone. A mapping is lengthened in place or moved by the system, without copying and
// without leaving the shorter one behind (an array that grows by doubling would otherwise keep
// its outgrown halves resident). On failure it throws std::bad_alloc and `p` is unchanged.
[[nodiscard]] void* reallocate_large_buffer(void* p, std::size_t old_bytes, std::size_t new_bytes, std::size_t keep_bytes);

// Whether buffers from large_buffer_from_bytes on are mappings: not in a sanitizer's build, where
// every buffer is a heap block so that reads and writes past its end are caught.
[[nodiscard]] bool large_buffers_are_mappings() noexcept;

// Bytes in a large buffer, freed with it.
struct LargeBufferDeleter {
    std::size_t bytes = 0;
    void operator()(char* p) const noexcept { free_large_buffer(p, bytes); }
};
using LargeBytes = std::unique_ptr<char[], LargeBufferDeleter>;
[[nodiscard]] inline LargeBytes allocate_large_bytes(std::size_t bytes) {
    return LargeBytes(static_cast<char*>(allocate_large_buffer(bytes)), LargeBufferDeleter{bytes});
}

// A vector's allocator over large buffers. Its elements are left as they are when the vector
// grows with resize(): for a list its owner writes element by element (the offsets of line starts
// the parser finds), zeroing would be a second pass over it, and the part never written is never
// touched.
template <class T>
struct LargeBufferAllocator {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = LargeBufferAllocator<U>;
    };
    LargeBufferAllocator() = default;
    template <class U>
    LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}

    [[nodiscard]] T* allocate(std::size_t n) { return static_cast<T*>(allocate_large_buffer(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { free_large_buffer(p, n * sizeof(T)); }
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    bool operator==(const LargeBufferAllocator<U>&) const noexcept {
        return true;
    }
};

}  // namespace esi
