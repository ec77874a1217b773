#pragma once
// Reading an input file whole, bounded: every front end (ESI XML, YAML sources, SII images,
// configs, templates) reads its input through this, so one limit guards them all.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace esi {

// The largest input file the front ends read (256 MiB; the largest vendor ESI file in the
// corpus has a few MiB). Reading takes about twice the file size in memory, so the bound keeps
// a hostile or mistaken input (a disk image, /dev/zero) from exhausting memory (docs/reliability.md).
inline constexpr std::uint64_t max_input_bytes = 256u << 20;

// The bytes of a file as read, in a buffer of their own followed by a NUL byte (a parser may rely
// on it), and read without first filling the buffer: a catalogue's zero-fill cost as much as
// parsing a tenth of it (docs/performance.md).
class FileBytes {
public:
    FileBytes() = default;
    FileBytes(std::unique_ptr<char[]> data, std::size_t size) : data_(std::move(data)), size_(size) {}
    [[nodiscard]] std::string_view view() const { return {data_.get(), size_}; }
    [[nodiscard]] std::size_t size() const { return size_; }

private:
    std::unique_ptr<char[]> data_;
    std::size_t size_ = 0;
};

// Reads a whole file into memory; nullopt and a message when it cannot be read or is larger
// than `max_bytes`.
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
