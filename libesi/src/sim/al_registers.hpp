#pragma once
// The ESC registers the slave stack uses through the PDI (ESC datasheet section II) and small
// helpers to read and write them little-endian.

#include <array>
#include <cstdint>

#include "esi/esc/pdi.hpp"

namespace esi::sim::reg {

inline constexpr std::uint16_t station_alias = 0x0012;
inline constexpr std::uint16_t al_control = 0x0120;
inline constexpr std::uint16_t al_status = 0x0130;
inline constexpr std::uint16_t al_status_code = 0x0134;
inline constexpr std::uint16_t al_event_request = 0x0220;
inline constexpr std::uint16_t watchdog_status_process_data = 0x0440;  // bit 0: 0 expired
inline constexpr std::uint16_t dc_activation = 0x0980;  // cyclic unit control (0x0980) and activation (0x0981)
inline constexpr std::uint16_t dc_sync0_cycle = 0x09A0;

// SyncManager n: 8 bytes from 0x0800 + 8n.
[[nodiscard]] constexpr std::uint16_t sm(std::uint32_t n) { return static_cast<std::uint16_t>(0x0800 + 8 * n); }
inline constexpr std::uint16_t sm_start = 0, sm_length = 2, sm_control = 4, sm_status = 5, sm_activate = 6, sm_pdi_control = 7;
inline constexpr std::uint8_t sm_status_mailbox_full = 0x08;
inline constexpr std::uint8_t sm_activate_enable = 0x01;
inline constexpr std::uint8_t sm_activate_repeat = 0x02;
inline constexpr std::uint8_t sm_pdi_repeat_ack = 0x02;

inline constexpr std::uint32_t al_event_control = 0x0001;
inline constexpr std::uint32_t al_event_watchdog_process_data = 0x0040;

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
