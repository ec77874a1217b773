#pragma once
// Test helper: EtherCAT frames as a master writes them (ETG.1000.4 §5), and EEPROM images with
// a chosen configuration area.

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include "esi/esc/esc.hpp"
#include "esi/esc/frame.hpp"

namespace esi::test {

class FrameBuilder {
public:
    // Appends a datagram; returns its index.
    std::size_t add(esc::Command command, std::uint16_t adp, std::uint16_t ado, std::vector<std::uint8_t> data = {},
                    std::uint16_t working_counter = 0) {
        datagrams_.push_back({command, adp, ado, std::move(data), working_counter});
        return datagrams_.size() - 1;
    }
    std::size_t add_logical(esc::Command command, std::uint32_t logical, std::vector<std::uint8_t> data) {
        return add(command, static_cast<std::uint16_t>(logical), static_cast<std::uint16_t>(logical >> 16), std::move(data));
    }
    // The EtherCAT payload: header and datagrams.
    [[nodiscard]] std::vector<std::uint8_t> bytes() const {
        std::vector<std::uint8_t> out(2);
        for (std::size_t i = 0; i < datagrams_.size(); ++i) {
            const Entry& e = datagrams_[i];
            const std::size_t at = out.size();
            out.resize(at + 10 + e.data.size() + 2);
            out[at] = static_cast<std::uint8_t>(e.command);
            out[at + 1] = static_cast<std::uint8_t>(i);
            put16(out, at + 2, e.adp);
            put16(out, at + 4, e.ado);
            put16(out, at + 6, static_cast<std::uint16_t>(e.data.size() | (i + 1 < datagrams_.size() ? 0x8000 : 0)));
            std::copy(e.data.begin(), e.data.end(), out.begin() + static_cast<std::ptrdiff_t>(at + 10));
            put16(out, at + 10 + e.data.size(), e.working_counter);
        }
        put16(out, 0, static_cast<std::uint16_t>((out.size() - 2) | 0x1000));
        return out;
    }
    // A datagram's data, working counter and ADP in a processed payload.
    [[nodiscard]] std::vector<std::uint8_t> data(std::span<const std::uint8_t> payload, std::size_t index) const {
        const std::size_t at = offset(index);
        return {payload.begin() + static_cast<std::ptrdiff_t>(at + 10),
                payload.begin() + static_cast<std::ptrdiff_t>(at + 10 + datagrams_[index].data.size())};
    }
    [[nodiscard]] std::uint16_t wkc(std::span<const std::uint8_t> payload, std::size_t index) const {
        const std::size_t at = offset(index) + 10 + datagrams_[index].data.size();
        return static_cast<std::uint16_t>(payload[at] | payload[at + 1] << 8);
    }
    [[nodiscard]] std::uint16_t adp(std::span<const std::uint8_t> payload, std::size_t index) const {
        const std::size_t at = offset(index) + 2;
        return static_cast<std::uint16_t>(payload[at] | payload[at + 1] << 8);
    }

private:
    struct Entry {
        esc::Command command;
        std::uint16_t adp, ado;
        std::vector<std::uint8_t> data;
        std::uint16_t working_counter;
    };
    static void put16(std::vector<std::uint8_t>& out, std::size_t at, std::uint16_t v) {
        out[at] = static_cast<std::uint8_t>(v);
        out[at + 1] = static_cast<std::uint8_t>(v >> 8);
    }
    [[nodiscard]] std::size_t offset(std::size_t index) const {
        std::size_t at = 2;
        for (std::size_t i = 0; i < index; ++i) at += 12 + datagrams_[i].data.size();
        return at;
    }
    std::vector<Entry> datagrams_;
};

// ETG.2010 configuration-area CRC (polynomial 0x07, initial 0xFF) over bytes 0..13.
inline std::uint8_t sii_crc(std::span<const std::uint8_t> bytes) {
    std::uint8_t crc = 0xFF;
    for (std::size_t i = 0; i < 14; ++i) {
        crc ^= bytes[i];
        for (int b = 0; b < 8; ++b) crc = static_cast<std::uint8_t>(crc & 0x80 ? (crc << 1) ^ 0x07 : crc << 1);
    }
    return crc;
}

// A 256-byte image: PDI control/ESC configuration in word 0, the alias in word 4, identity in
// words 8..13, a correct checksum, the rest erased.
inline std::vector<std::uint8_t> eeprom_image(std::uint8_t pdi_control, std::uint8_t esc_configuration = 0,
                                              std::uint16_t alias = 0) {
    std::vector<std::uint8_t> image(256, 0xFF);
    for (std::size_t i = 0; i < 16; ++i) image[i] = 0;
    image[0] = pdi_control;
    image[1] = esc_configuration;
    image[8] = static_cast<std::uint8_t>(alias);
    image[9] = static_cast<std::uint8_t>(alias >> 8);
    const std::uint8_t identity[] = {0x9A, 0x00, 0x00, 0x00, 0x34, 0x12, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00};
    std::copy(std::begin(identity), std::end(identity), image.begin() + 16);
    image[14] = sii_crc(image);
    image[15] = 0;
    return image;
}

// Passes a payload through the ESCs (slave 0 first); returns the outcome.
inline esc::FrameOutcome run(std::vector<std::uint8_t>& payload, std::initializer_list<esc::Esc*> line,
                             std::uint64_t time_ns = 1'000'000) {
    std::vector<esc::Esc*> escs(line);
    std::vector<esc::DatagramSlot> scratch;
    return esc::pass_frame(payload, escs, {time_ns, 500}, scratch);
}

}  // namespace esi::test
