#include "esi/lsp/framing.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <string_view>
#include <unistd.h>

namespace esi::lsp {

namespace {

constexpr std::size_t read_chunk = 64 * 1024;
constexpr std::string_view length_header = "content-length";

std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string_view trim(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
    return text;
}

bool is_token(std::string_view name) {
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
    });
}

struct Header {
    std::optional<std::size_t> length;
    std::string problem;
};

// Parses "Name: value" lines (terminated by \r\n or \n).
Header parse_header(std::string_view block) {
    Header header;
    while (!block.empty()) {
        const std::size_t eol = block.find('\n');
        std::string_view line = block.substr(0, eol);
        block = eol == std::string_view::npos ? std::string_view{} : block.substr(eol + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.empty()) continue;
        const std::size_t colon = line.find(':');
        const std::string_view name = colon == std::string_view::npos ? line : line.substr(0, colon);
        if (colon == std::string_view::npos || !is_token(name)) {
            header.problem = "header line is not `Name: value`";
            return header;
        }
        if (lower(name) != length_header) continue;  // Content-Type and others: nothing to do with them
        const std::string_view value = trim(line.substr(colon + 1));
        std::size_t length = 0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), length);
        if (value.empty() || error != std::errc{} || end != value.data() + value.size()) {
            header.problem = "Content-Length is not a number: " + std::string(value.substr(0, 40));
            return header;
        }
        header.length = length;
    }
    if (!header.length) header.problem = "no Content-Length header";
    return header;
}

}  // namespace

bool MessageReader::fill() {
    if (at_end_) return false;
    compact();
    char chunk[read_chunk];
    const std::ptrdiff_t got = read_(chunk, read_chunk);
    if (got <= 0) {
        at_end_ = true;
        return false;
    }
    buffer_.append(chunk, static_cast<std::size_t>(got));
    return true;
}

void MessageReader::compact() {
    if (start_ == 0) return;
    if (start_ == buffer_.size()) {
        buffer_.clear();
        start_ = 0;
    } else if (start_ >= buffer_.size() / 2) {
        buffer_.erase(0, start_);
        start_ = 0;
    }
}

Frame MessageReader::next() {
    for (;;) {
        const std::string_view pending = std::string_view(buffer_).substr(start_);
        // The header block ends at the first empty line.
        std::size_t block_end = std::string_view::npos;
        std::size_t terminator = 0;
        const std::size_t crlf = pending.find("\r\n\r\n");
        const std::size_t lf = pending.find("\n\n");
        if (crlf != std::string_view::npos && (lf == std::string_view::npos || crlf < lf)) {
            block_end = crlf;
            terminator = 4;
        } else if (lf != std::string_view::npos) {
            block_end = lf;
            terminator = 2;
        }
        if (block_end == std::string_view::npos || block_end > max_header_bytes) {
            if (pending.size() > max_header_bytes) {
                // No header in sight: drop the bytes up to a later Content-Length (keeping a tail
                // that may be the start of one).
                const std::size_t found = lower(pending).find(length_header, 1);
                start_ += found != std::string::npos ? found : pending.size() - (length_header.size() - 1);
                return {Frame::Kind::bad_header, {}, "bytes outside any message skipped"};
            }
            if (!fill()) return {};
            continue;
        }
        const Header header = parse_header(pending.substr(0, block_end));
        if (!header.length) {
            // Garbage before a header ("xyzContent-Length: 7"): resume at the header.
            const std::size_t found = lower(pending.substr(0, block_end)).find(length_header, 1);
            if (found != std::string::npos) {
                start_ += found;
                return {Frame::Kind::bad_header, {}, "bytes outside any message skipped"};
            }
            start_ += block_end + terminator;
            return {Frame::Kind::bad_header, {}, header.problem};
        }
        start_ += block_end + terminator;
        const std::size_t length = *header.length;
        if (length > max_body_) {
            std::size_t left = length;
            for (;;) {
                const std::size_t take = std::min(left, buffer_.size() - start_);
                start_ += take;
                left -= take;
                if (left == 0 || !fill()) break;
            }
            if (left != 0) return {};
            return {Frame::Kind::oversize, {},
                    "message of " + std::to_string(length) + " bytes is over the limit of " + std::to_string(max_body_)};
        }
        if (buffer_.size() - start_ < length) {
            compact();
            buffer_.reserve(start_ + length + read_chunk);
            while (buffer_.size() - start_ < length)
                if (!fill()) return {};  // the client went away in the middle of a message
        }
        Frame message{Frame::Kind::message, buffer_.substr(start_, length), {}};
        start_ += length;
        return message;
    }
}

bool MessageWriter::write(const std::string& body) {
    const std::string framed = frame(body);
    const std::lock_guard lock(mutex_);
    if (broken_) return false;
    if (!write_(framed.data(), framed.size())) broken_ = true;
    return !broken_;
}

std::string frame(const std::string& body) {
    return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

ReadSome read_fd(int fd) {
    return [fd](char* buffer, std::size_t size) -> std::ptrdiff_t {
        for (;;) {
            const ssize_t got = ::read(fd, buffer, size);
            if (got < 0 && errno == EINTR) continue;
            return got;
        }
    };
}

MessageWriter::WriteAll write_fd(int fd) {
    return [fd](const char* data, std::size_t size) {
        while (size > 0) {
            const ssize_t put = ::write(fd, data, size);
            if (put < 0 && errno == EINTR) continue;
            if (put <= 0) return false;
            data += put;
            size -= static_cast<std::size_t>(put);
        }
        return true;
    };
}

}  // namespace esi::lsp
