#pragma once
// The base protocol of the Language Server Protocol: JSON-RPC messages framed by a header block
//   Content-Length: N\r\n
//   [Content-Type: ...\r\n]
//   \r\n
// followed by N bytes of body. The reader takes bytes in whatever pieces the pipe gives them and
// recovers from a client that sends garbage: a bad header block is skipped up to the next
// "Content-Length", an oversize body is read and dropped (never held), so one bad message costs
// one error, not the session.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

namespace esi::lsp {

// Up to here a body is held in memory: a 256 MiB document (esi::max_input_bytes) with the
// escaping JSON adds. A longer body is skipped.
inline constexpr std::size_t max_body_bytes = std::size_t{320} << 20;
// A header block longer than this is garbage, not headers.
inline constexpr std::size_t max_header_bytes = 8192;

// Reads up to `size` bytes into `buffer`: the count, 0 at end of input, negative on an error.
using ReadSome = std::function<std::ptrdiff_t(char* buffer, std::size_t size)>;

struct Frame {
    enum class Kind {
        message,       // body holds one message's bytes
        bad_header,    // a header block without a usable Content-Length, or bytes that are no header
        oversize,      // Content-Length above the limit: the body was skipped
        end_of_input,  // the client closed the stream (possibly in the middle of a message)
    };
    Kind kind = Kind::end_of_input;
    std::string body;
    std::string problem;  // why, for bad_header and oversize
};

class MessageReader {
public:
    explicit MessageReader(ReadSome read, std::size_t max_body = max_body_bytes)
        : read_(std::move(read)), max_body_(max_body) {}
    [[nodiscard]] Frame next();

private:
    bool fill();  // reads more into buffer_; false at end of input
    void compact();

    ReadSome read_;
    std::size_t max_body_;
    std::string buffer_;
    std::size_t start_ = 0;  // bytes before this in buffer_ are consumed
    bool at_end_ = false;
};

// Writes framed messages; several threads may write (the lint worker publishes diagnostics while
// the main thread answers requests), each message goes out whole.
class MessageWriter {
public:
    // Writes all of `size` bytes; false when the stream is gone.
    using WriteAll = std::function<bool(const char* data, std::size_t size)>;
    explicit MessageWriter(WriteAll write) : write_(std::move(write)) {}
    // False once the stream is gone (later writes are dropped).
    bool write(const std::string& body);

private:
    std::mutex mutex_;
    WriteAll write_;
    bool broken_ = false;
};

// The frame of one body: header block and body.
[[nodiscard]] std::string frame(const std::string& body);

// ReadSome / WriteAll over a file descriptor (retrying EINTR and short writes).
[[nodiscard]] ReadSome read_fd(int fd);
[[nodiscard]] MessageWriter::WriteAll write_fd(int fd);

}  // namespace esi::lsp
