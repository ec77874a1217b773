#include "esi/io/read_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <system_error>

namespace esi {

std::optional<std::string> read_file_bytes(const std::filesystem::path& path, std::string& error, std::uint64_t max_bytes) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        error = "is a directory";
        return std::nullopt;
    }
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) {
        error = std::error_code(errno, std::generic_category()).message();
        return std::nullopt;
    }
    auto too_large = [&] {
        error = "larger than " + std::to_string(max_bytes >> 20) + " MiB, the input size limit";
        std::fclose(file);
        return std::nullopt;
    };
    // A regular file is read into a buffer of its size in one call, so it is neither copied nor
    // over-allocated. Whatever the size did not cover (a file that grew, a pipe, a device) is
    // appended in chunks, bounded by max_bytes like the announced size.
    std::string bytes;
    std::error_code size_error;
    const std::uintmax_t size = std::filesystem::file_size(path, size_error);
    if (!size_error && size > max_bytes) return too_large();
    if (!size_error) {
        bytes.resize(static_cast<std::size_t>(size));
        bytes.resize(std::fread(bytes.data(), 1, bytes.size(), file));
    }
    char buffer[1 << 16];
    for (bool more = bytes.size() == size || size_error; more;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
        bytes.append(buffer, n);
        if (bytes.size() > max_bytes) return too_large();
        more = n == sizeof buffer;
    }
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed) {
        error = "read error";
        return std::nullopt;
    }
    return bytes;
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
        error = "larger than " + std::to_string(max_bytes >> 20) + " MiB, the input size limit";
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
            error = "larger than " + std::to_string(max_bytes >> 20) + " MiB, the input size limit";
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
            error = "larger than " + std::to_string(max_bytes >> 20) + " MiB, the input size limit";
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
