#pragma once
// Distributed clocks: the bits of an ESI's Dc/OpMode/AssignActivate word, which a master writes
// to 0x0980 (low byte, cyclic unit control) and 0x0981 (high byte, activation) (ESC datasheet
// section II 0x0980/0x0981; ETG.2000 Dc).

#include <cstdint>

namespace esi::ethercat::assign_activate {

inline constexpr std::uint16_t cyclic_operation = 0x0100;  // 0x0981 bit 0: cyclic operation on
inline constexpr std::uint16_t sync0 = 0x0200;             // 0x0981 bit 1: SYNC0 generated
inline constexpr std::uint16_t sync1 = 0x0400;             // 0x0981 bit 2: SYNC1 generated
// What a device synchronised to SYNC0 needs: cyclic operation and SYNC0.
inline constexpr std::uint16_t sync0_cyclic = cyclic_operation | sync0;

}  // namespace esi::ethercat::assign_activate
