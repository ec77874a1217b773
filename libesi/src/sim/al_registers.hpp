#pragma once
// Small helpers with which the slave stack reads and writes the ESC's registers through the PDI,
// little-endian; the registers are named in the protocol layer (esi/ethercat/registers.hpp).

#include <array>
#include <cstdint>

#include "esi/esc/pdi.hpp"
#include "esi/ethercat/registers.hpp"

namespace esi::sim::reg {

// The register map is the protocol layer's (esi/ethercat/registers.hpp).
using namespace ethercat::reg;

[[nodiscard]] inline std::uint8_t read_u8(esc::Pdi& pdi, std::uint16_t address) {
    std::array<std::uint8_t, 1> b{};
    pdi.read(address, b);
    return b[0];
}
[[nodiscard]] inline std::uint16_t read_u16(esc::Pdi& pdi, std::uint16_t address) {
    std::array<std::uint8_t, 2> b{};
    pdi.read(address, b);
    return static_cast<std::uint16_t>(b[0] | (b[1] << 8));
}
[[nodiscard]] inline std::uint32_t read_u32(esc::Pdi& pdi, std::uint16_t address) {
    std::array<std::uint8_t, 4> b{};
    pdi.read(address, b);
    return static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) | (static_cast<std::uint32_t>(b[2]) << 16) |
           (static_cast<std::uint32_t>(b[3]) << 24);
}
inline void write_u8(esc::Pdi& pdi, std::uint16_t address, std::uint8_t value) {
    const std::array<std::uint8_t, 1> b{value};
    pdi.write(address, b);
}
inline void write_u16(esc::Pdi& pdi, std::uint16_t address, std::uint16_t value) {
    const std::array<std::uint8_t, 2> b{static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8)};
    pdi.write(address, b);
}

// One SyncManager's registers as read (only the 6 bytes without side effects: reading the
// activate register 0x0806 would acknowledge an SM change event).
struct SmRegisters {
    std::uint16_t start = 0;
    std::uint16_t length = 0;
    std::uint8_t control = 0;
    std::uint8_t status = 0;
    std::uint8_t activate = 0;
};

[[nodiscard]] inline SmRegisters read_sm(esc::Pdi& pdi, std::uint32_t n, bool with_activate) {
    std::array<std::uint8_t, 7> b{};
    pdi.read(sm(n), std::span<std::uint8_t>(b.data(), with_activate ? 7 : 6));
    return {static_cast<std::uint16_t>(b[0] | (b[1] << 8)), static_cast<std::uint16_t>(b[2] | (b[3] << 8)), b[4], b[5], b[6]};
}

}  // namespace esi::sim::reg
