#include "xml/parse_buffer.hpp"

#include <algorithm>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace esi::xml_reader {

// To give pages back, the copy is (on Linux) an anonymous mapping of its own, so that
// madvise(MADV_DONTNEED) returns its pages at once (they read as zeros afterwards) whatever the
// allocator does with the rest of the heap. Otherwise it is a plain allocation.
ParseBuffer::ParseBuffer(std::string_view text, bool give_back_pages)
    : size_(text.size()), capacity_(std::max<std::size_t>(text.size(), 1)) {
#if defined(__linux__)
    if (give_back_pages) {
        void* mapped = mmap(nullptr, capacity_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (mapped == MAP_FAILED) throw std::bad_alloc();
        data_ = static_cast<char*>(mapped);
        mapped_ = true;
    }
#else
    (void)give_back_pages;
#endif
    if (!mapped_) data_ = new char[capacity_];
    if (!text.empty()) std::memcpy(data_, text.data(), text.size());
}

ParseBuffer::~ParseBuffer() {
#if defined(__linux__)
    if (mapped_) {
        munmap(data_, capacity_);
        return;
    }
#endif
    delete[] data_;
}

void ParseBuffer::give_back(std::size_t begin, std::size_t end) {
#if defined(__linux__)
    if (!mapped_) return;
    static const std::size_t page = [] {
        const long size = sysconf(_SC_PAGESIZE);
        return size > 0 ? static_cast<std::size_t>(size) : std::size_t{4096};
    }();
    begin = std::max(begin, given_back_end_);
    end = std::min(end, size_);
    const std::size_t first = (begin + page - 1) / page * page;  // the mapping starts on a page
    const std::size_t last = end / page * page;
    if (first >= last) return;
    // A failure only leaves the pages where they are.
    if (madvise(data_ + first, last - first, MADV_DONTNEED) == 0) given_back_end_ = last;
#else
    (void)begin;
    (void)end;
#endif
}

}  // namespace esi::xml_reader
