#pragma once
// How much ESC memory a SyncManager occupies, for the rules that lay SMs out in the ESC's address
// space (sm-overlap, sm-address-area).

#include <cstdint>

#include "check/queries.hpp"

namespace esi::rules {

// Below 0x1000 lies the ESC's register area; process RAM (mailboxes, process-data buffers) starts
// at 0x1000 (ESC datasheet section II, address space overview).
constexpr std::uint32_t process_memory_start = 0x1000;

// Bytes of the PDOs a device assigns to SM `number` by default (Pdo@Sm).
[[nodiscard]] std::uint64_t default_pdo_bytes(const Device& device, std::size_t number);

// The size SM `number` has when the master starts it: a process-data SM's length comes from the
// PDOs assigned to it (DefaultSize then only says how much room the firmware reserves); mailbox SMs
// and process-data SMs without default PDOs take DefaultSize (0 when absent).
[[nodiscard]] std::uint64_t effective_size(const Device& device, std::size_t number);

// Whether `sm` occupies three consecutive buffers of `size` (buffered mode, ESC datasheet "3-buffer
// mode") rather than one. Mailbox SMs, SMs in the register area and the 1-byte SMs of a digital-I/O
// ESC count once (see the definition for why).
[[nodiscard]] bool occupies_three_buffers(const Device& device, const SyncManager& sm, std::uint64_t size);

// Whether the ESC's PDI is digital I/O: SII word 0 (ConfigData byte 0, PDI control register 0x0140)
// = 0x04 (ESC datasheet section II, PDI control).
[[nodiscard]] bool has_digital_io_pdi(const Device& device);

}  // namespace esi::rules
