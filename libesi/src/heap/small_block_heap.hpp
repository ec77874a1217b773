#pragma once
// The small-block heap of libesi's tools: a replacement of the global operator new and delete
// that the executables (cli/, bench/) link, not the library. A model is built of many small
// blocks (std::string buffers over 15 characters, vectors of names, verbatim elements) that are
// all freed together when the next file starts; glibc's malloc serves that pattern from its slow
// paths (its per-thread cache holds seven blocks of a size; the rest are sorted into bins and
// coalesced): 13% of a one-thread lint's instructions on the open corpus went to malloc and free.
//
// Blocks up to max_small_block bytes come from 64 KiB pages of one size class (16-byte steps)
// carved out of one reservation of address space; each thread keeps a free list per class, so an
// allocation is a pop and a free a push, without locks. A block freed on another thread joins
// that thread's list. When a thread ends, its lists go to a shared pool the next page request of
// any thread takes first. Pages are never given back to the system: a file's model is freed to
// the lists the next file's model is built from.
//
// The heap steps aside (everything goes to malloc) when the reservation cannot be made, when the
// process has an address-space limit (RLIMIT_AS: the limit then means what it says), and in
// builds with AddressSanitizer, which must see every allocation. Larger blocks always go to
// malloc.

#include <cstddef>
#include <cstdint>
#include <optional>

namespace esi::heap {

inline constexpr std::size_t small_block_step = 16;
inline constexpr std::size_t max_small_block = 1024;
inline constexpr std::size_t small_block_page = std::size_t{64} << 10;

// The address space reserved for small blocks: none under an address-space limit, else 4 GiB.
// (A function of the limit so that the rule can be tested without changing the test's limits.)
[[nodiscard]] std::size_t reservation_for(std::optional<std::uint64_t> address_space_limit);

// True when the heap is in use: it reserved its space (which it does at the first call here or
// at the first small allocation).
[[nodiscard]] bool small_block_heap_active();
// True when p is a block of the small-block heap (false for blocks malloc gave).
[[nodiscard]] bool is_small_block(const void* p);
// Pages taken from the reservation so far.
[[nodiscard]] std::size_t small_block_pages();

}  // namespace esi::heap
