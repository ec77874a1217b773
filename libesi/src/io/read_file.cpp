#include "esi/io/read_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>

namespace esi {

namespace {

// The message of every reader for an input over the size limit.
std::string too_large(std::uint64_t max_bytes) {
    return "larger than " + std::to_string(max_bytes >> 20) + " MiB, the input size limit";
}

// A buffer of `size` bytes (and a NUL after them) whose bytes are not initialised: they are read
// into right after.
struct Growing {
    LargeBytes data;
    std::size_t size = 0;
    std::size_t capacity = 0;

    void reserve(std::size_t n) {
        if (data && n <= capacity) return;
        LargeBytes bigger = allocate_large_bytes(n + 1);
        if (size) std::memcpy(bigger.get(), data.get(), size);
        data = std::move(bigger);
        capacity = n;
    }
};

// Reads `file` whole (its size as announced, then whatever follows), bounded by max_bytes; false
// and `error` set on failure.
template <class Sink>
bool read_all(std::FILE* file, const std::filesystem::path& path, std::uint64_t max_bytes, std::string& error, Sink& sink) {
    // A regular file is read into a buffer of its size in one call, so it is neither copied nor
    // over-allocated. Whatever the size did not cover (a file that grew, a pipe, a device) is
    // appended in chunks, bounded by max_bytes like the announced size.
    std::error_code size_error;
    const std::uintmax_t size = std::filesystem::file_size(path, size_error);
    if (!size_error && size > max_bytes) {
        error = too_large(max_bytes);
        return false;
    }
    if (!size_error) sink.read(file, static_cast<std::size_t>(size));
    char buffer[1 << 16];
    for (bool more = sink.size() == size || size_error; more;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
        sink.append(buffer, n);
        if (sink.size() > max_bytes) {
            error = too_large(max_bytes);
            return false;
        }
        more = n == sizeof buffer;
    }
    if (std::ferror(file) != 0) {
        error = "read error";
        return false;
    }
    return true;
}

std::FILE* open_for_reading(const std::filesystem::path& path, std::string& error) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        error = "is a directory";
        return nullptr;
    }
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) error = std::error_code(errno, std::generic_category()).message();
    return file;
}

struct StringSink {
    std::string bytes;
    void read(std::FILE* file, std::size_t n) {
        bytes.resize(n);
        bytes.resize(std::fread(bytes.data(), 1, n, file));
    }
    void append(const char* p, std::size_t n) { bytes.append(p, n); }
    [[nodiscard]] std::size_t size() const { return bytes.size(); }
};

struct BufferSink {
    Growing buffer;
    void read(std::FILE* file, std::size_t n) {
        buffer.reserve(n);
        buffer.size = std::fread(buffer.data.get(), 1, n, file);
    }
    void append(const char* p, std::size_t n) {
        if (buffer.size + n > buffer.capacity) buffer.reserve(std::max(buffer.capacity * 2, buffer.size + n));
        std::memcpy(buffer.data.get() + buffer.size, p, n);
        buffer.size += n;
    }
    [[nodiscard]] std::size_t size() const { return buffer.size; }
};

}  // namespace

FileBytes::FileBytes(FileBytes&& other) noexcept
    : data_(std::move(other.data_)), map_(other.map_), map_length_(other.map_length_), size_(other.size_) {
    other.map_ = nullptr;
    other.map_length_ = 0;
    other.size_ = 0;
}

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
    if (this != &other) {
        if (map_) ::munmap(map_, map_length_);
        data_ = std::move(other.data_);
        map_ = std::exchange(other.map_, nullptr);
        map_length_ = std::exchange(other.map_length_, 0);
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

FileBytes::~FileBytes() {
    if (map_) ::munmap(map_, map_length_);
}

std::optional<FileBytes> FileBytes::map(int fd, std::size_t size) {
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    // The file's pages and one page of zeros after them, so that a NUL byte follows the bytes even
    // when they fill their last page: an anonymous reservation, the file mapped over its start.
    const std::size_t length = (size + page - 1) / page * page + page;
    void* reserved = ::mmap(nullptr, length, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (reserved == MAP_FAILED) return std::nullopt;
    if (size > 0 && ::mmap(reserved, size, PROT_READ, MAP_PRIVATE | MAP_FIXED, fd, 0) == MAP_FAILED) {
        ::munmap(reserved, length);
        return std::nullopt;
    }
    FileBytes bytes;
    bytes.map_ = static_cast<char*>(reserved);
    bytes.map_length_ = length;
    bytes.size_ = size;
    return bytes;
}

void FileBytes::release(std::size_t from, std::size_t to) const {
    if (!map_) return;
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const std::size_t first = (from + page - 1) / page * page;
    const std::size_t last = std::min(to, size_) / page * page;
    if (first < last) ::madvise(map_ + first, last - first, MADV_DONTNEED);
}

std::optional<FileBytes> read_file_buffer(const std::filesystem::path& path, std::string& error, std::uint64_t max_bytes) {
    // A big regular file is mapped; anything else (or a mapping the system refuses) is read.
    if (const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK); fd >= 0) {
        struct stat st {};
        std::optional<FileBytes> mapped;
        if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) >= map_from_bytes &&
            static_cast<std::uint64_t>(st.st_size) <= max_bytes)
            mapped = FileBytes::map(fd, static_cast<std::size_t>(st.st_size));
        ::close(fd);
        if (mapped) return mapped;
    }
    std::FILE* file = open_for_reading(path, error);
    if (!file) return std::nullopt;
    BufferSink sink;
    sink.buffer.reserve(0);
    const bool ok = read_all(file, path, max_bytes, error, sink);
    std::fclose(file);
    if (!ok) return std::nullopt;
    sink.buffer.data[sink.buffer.size] = '\0';
    return FileBytes(std::move(sink.buffer.data), sink.buffer.size);
}

std::optional<std::string> read_file_bytes(const std::filesystem::path& path, std::string& error, std::uint64_t max_bytes) {
    std::FILE* file = open_for_reading(path, error);
    if (!file) return std::nullopt;
    StringSink sink;
    const bool ok = read_all(file, path, max_bytes, error, sink);
    std::fclose(file);
    if (!ok) return std::nullopt;
    return std::move(sink.bytes);
}

std::optional<std::string> read_regular_file_bytes(const std::filesystem::path& path, std::string& error, std::uint64_t max_bytes) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        error = std::error_code(errno, std::generic_category()).message();
        return std::nullopt;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        error = S_ISDIR(st.st_mode) ? "is a directory" : "not a regular file";
        ::close(fd);
        return std::nullopt;
    }
    if (static_cast<std::uint64_t>(st.st_size) > max_bytes) {
        ::close(fd);
        error = too_large(max_bytes);
        return std::nullopt;
    }
    std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
    std::size_t have = 0;
    for (;;) {
        if (have == bytes.size()) bytes.resize(bytes.size() + (1 << 16));  // the file may have grown
        const ssize_t n = ::read(fd, bytes.data() + have, bytes.size() - have);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = std::error_code(errno, std::generic_category()).message();
            ::close(fd);
            return std::nullopt;
        }
        if (n == 0) break;
        have += static_cast<std::size_t>(n);
        if (have > max_bytes) {
            ::close(fd);
            error = too_large(max_bytes);
            return std::nullopt;
        }
    }
    ::close(fd);
    bytes.resize(have);
    return bytes;
}

std::optional<std::string> read_stdin_bytes(std::string& error, std::uint64_t max_bytes) {
    std::string bytes;
    char buffer[1 << 16];
    for (;;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, stdin);
        bytes.append(buffer, n);
        if (bytes.size() > max_bytes) {
            error = too_large(max_bytes);
            return std::nullopt;
        }
        if (n < sizeof buffer) break;
    }
    if (std::ferror(stdin)) {
        error = "read error";
        return std::nullopt;
    }
    return bytes;
}

}  // namespace esi
