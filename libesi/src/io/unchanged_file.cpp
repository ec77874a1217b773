#include "io/unchanged_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

namespace esi::io_detail {

bool holds_exactly(const std::filesystem::path& path, std::string_view content) {
    // O_NONBLOCK: opening a FIFO in the target's place would otherwise wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return false;
    struct stat info {};
    // The size first: most changed outputs differ in length, and a FIFO or device is never read.
    bool same = ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && static_cast<std::size_t>(info.st_size) == content.size();
    std::array<char, 65536> buffer{};
    std::size_t offset = 0;
    while (same) {
        const ssize_t n = ::read(fd, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) same = false;
        if (n <= 0) break;
        const auto count = static_cast<std::size_t>(n);
        same = offset + count <= content.size() && std::memcmp(buffer.data(), content.data() + offset, count) == 0;
        offset += count;
    }
    ::close(fd);
    return same && offset == content.size();
}

}  // namespace esi::io_detail
