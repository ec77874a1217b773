#pragma once
// Little-endian byte writer and bounds-checked reader for SII images (internal). The reader
// never reads past its span: a read beyond the end returns 0 and sets `overrun`, so decoders
// can check once per record instead of before every field.

#include <cstdint>
#include <span>
#include <vector>

namespace esi::sii {

class ByteWriter {
public:
    ByteWriter() = default;
    explicit ByteWriter(std::vector<std::uint8_t> start) : out_(std::move(start)) {}
    void u8(std::uint8_t v) { out_.push_back(v); }
    void u16(std::uint16_t v) {
        out_.push_back(static_cast<std::uint8_t>(v & 0xFF));
        out_.push_back(static_cast<std::uint8_t>(v >> 8));
    }
    void u32(std::uint32_t v) {
        u16(static_cast<std::uint16_t>(v & 0xFFFF));
        u16(static_cast<std::uint16_t>(v >> 16));
    }
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const std::uint8_t*>(data);
        out_.insert(out_.end(), p, p + size);
    }
    void pad_to_word(std::uint8_t pad) {
        if (out_.size() % 2 != 0) out_.push_back(pad);
    }
    [[nodiscard]] std::size_t size() const { return out_.size(); }
    [[nodiscard]] std::vector<std::uint8_t> take() { return std::move(out_); }

private:
    std::vector<std::uint8_t> out_;
};

class ByteReader {
public:
    explicit ByteReader(std::span<const std::uint8_t> data) : data_(data) {}
    [[nodiscard]] std::size_t position() const { return pos_; }
    [[nodiscard]] std::size_t remaining() const { return pos_ < data_.size() ? data_.size() - pos_ : 0; }
    [[nodiscard]] bool overrun() const { return overrun_; }
    std::uint8_t u8() {
        if (pos_ >= data_.size()) {
            overrun_ = true;
            return 0;
        }
        return data_[pos_++];
    }
    std::uint16_t u16() {
        const std::uint8_t lo = u8();
        const std::uint8_t hi = u8();
        return static_cast<std::uint16_t>(lo | (hi << 8));
    }
    std::uint32_t u32() {
        const std::uint32_t lo = u16();
        const std::uint32_t hi = u16();
        return lo | (hi << 16);
    }
    void skip(std::size_t n) {
        if (n > remaining()) {
            overrun_ = true;
            pos_ = data_.size();
        } else {
            pos_ += n;
        }
    }

private:
    std::span<const std::uint8_t> data_;
    std::size_t pos_ = 0;
    bool overrun_ = false;
};

inline std::uint16_t read_word(std::span<const std::uint8_t> data, std::size_t word_address) {
    const std::size_t at = word_address * 2;
    if (at + 1 >= data.size()) return 0;
    return static_cast<std::uint16_t>(data[at] | (data[at + 1] << 8));
}

}  // namespace esi::sii
