#pragma once
// Reading an input file whole, bounded: every front end (ESI XML, YAML sources, SII images,
// configs, templates) reads its input through this, so one limit guards them all.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "esi/large_buffer.hpp"

namespace esi {

// The largest input file the front ends read (256 MiB; the largest vendor ESI file in the
// corpus has a few MiB). Reading takes about twice the file size in memory, so the bound keeps
// a hostile or mistaken input (a disk image, /dev/zero) from exhausting memory (docs/reliability.md).
inline constexpr std::uint64_t max_input_bytes = 256u << 20;

// The bytes of a file, followed by a NUL byte (a parser may rely on it): read into a buffer of
// their own without first filling it (a catalogue's zero-fill cost as much as parsing a tenth of
// it), or, for a big regular file, mapped (docs/performance.md). Mapped bytes whose memory the
// reader lets go (release()) are the file's pages in the page cache: they are read again from
// there when touched. A mapped file that another process truncates while it is read ends the
// process with SIGBUS, as it does for every program that maps its input (ripgrep, git).
class FileBytes {
public:
    FileBytes() = default;
    FileBytes(LargeBytes data, std::size_t size) : data_(std::move(data)), size_(size) {}
    FileBytes(FileBytes&& other) noexcept;
    FileBytes& operator=(FileBytes&& other) noexcept;
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;
    ~FileBytes();

    // Maps `size` bytes of the open regular file `fd` (and a page of zeros after them); nothing when
    // the system refuses.
    [[nodiscard]] static std::optional<FileBytes> map(int fd, std::size_t size);

    [[nodiscard]] std::string_view view() const { return {map_ ? map_ : data_.get(), size_}; }
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] bool mapped() const { return map_ != nullptr; }
    // The memory of bytes [from, to) may go: they have been read. Only a mapping gives back memory
    // (its whole pages in the range); a buffer keeps its bytes.
    void release(std::size_t from, std::size_t to) const;

private:
    LargeBytes data_;
    char* map_ = nullptr;
    std::size_t map_length_ = 0;
    std::size_t size_ = 0;
};

// Files from this size on are mapped rather than read into a buffer.
inline constexpr std::uint64_t map_from_bytes = std::uint64_t{8} << 20;

// Reads a whole file into memory (or maps it, from map_from_bytes on); nullopt and a message when
// it cannot be read or is larger than `max_bytes`.
[[nodiscard]] std::optional<FileBytes> read_file_buffer(const std::filesystem::path& path, std::string& error,
                                                        std::uint64_t max_bytes = max_input_bytes);
// The same into a string.
[[nodiscard]] std::optional<std::string> read_file_bytes(const std::filesystem::path& path, std::string& error,
                                                         std::uint64_t max_bytes = max_input_bytes);

// The same for a file that must be a regular file (a cache, a library file found in a folder):
// opened without blocking (a FIFO in its place would block open() until a writer comes) and
// checked with fstat on the open descriptor, so that a FIFO, device or directory is refused
// with a message instead of hanging or reading without end.
[[nodiscard]] std::optional<std::string> read_regular_file_bytes(const std::filesystem::path& path, std::string& error,
                                                                 std::uint64_t max_bytes = max_input_bytes);

// Reads standard input to its end, bounded like a file: a stream that never ends (a device, a
// runaway pipe) gives nullopt and a message rather than an exhausted machine.
[[nodiscard]] std::optional<std::string> read_stdin_bytes(std::string& error, std::uint64_t max_bytes = max_input_bytes);

}  // namespace esi
