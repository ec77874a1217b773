#include "esi/config_crc.hpp"

namespace esi {

std::uint8_t config_crc(std::span<const std::uint8_t> config_area) {
    std::uint8_t crc = 0xFF;
    for (const std::uint8_t byte : config_area) {
        crc ^= byte;
        for (int bit = 0; bit < 8; ++bit) crc = static_cast<std::uint8_t>((crc & 0x80) ? ((crc << 1) ^ 0x07) : (crc << 1));
    }
    return crc;
}

}  // namespace esi
