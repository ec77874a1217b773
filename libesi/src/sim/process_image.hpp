#pragma once
// The process data of the device as its PDO assignment (0x1C10 + SM) and mapping (0x16xx,
// 0x1Axx) objects lay it out at this moment (ETG.1000.6 5.6.7.4): per process-data SM the
// mapped entries with their bit offsets in the SM's buffer. Laid out again whenever the device
// enters SAFEOP, so a master's remapping in PREOP takes effect, and used to check the SM
// lengths the master configured.

#include <cstdint>
#include <span>
#include <vector>

#include "sim/coe_dictionary.hpp"
#include "sim/sdo_access.hpp"

namespace esi::sim {

struct MappedEntry {
    std::uint16_t index = 0;  // 0 (or a data-type index): a gap
    std::uint8_t subindex = 0;
    std::uint32_t bit_offset = 0;  // in the SM buffer
    std::uint32_t bit_len = 0;
};

struct SmProcessData {
    std::uint8_t sm = 0;
    SmRole role = SmRole::outputs;
    std::uint32_t bits = 0;
    std::vector<MappedEntry> entries;
    [[nodiscard]] std::uint32_t bytes() const { return (bits + 7u) / 8u; }
};

// One SmProcessData per SM whose role is outputs or inputs, in SM order.
[[nodiscard]] std::vector<SmProcessData> lay_out_process_data(const CoeDictionary& dictionary,
                                                              const std::vector<SmRole>& roles);

// The mapped objects' values into an SM buffer (inputs) and back (outputs). Entries whose object
// is missing leave their bits as they are.
void objects_to_buffer(const SmProcessData& layout, const CoeDictionary& dictionary, std::span<std::uint8_t> buffer);
void buffer_to_objects(const SmProcessData& layout, std::span<const std::uint8_t> buffer, CoeDictionary& dictionary);

}  // namespace esi::sim
