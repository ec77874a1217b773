#pragma once
// Reading and writing the dictionary's entries the way a device's CoE server checks them: the
// object and sub-index exist, the entry may be read or written in the AL state, the length fits
// the type, complete access is declared, and the PDO mapping (0x16xx, 0x1Axx) and assignment
// (0x1C10 + SM) objects follow their protocol (ETG.1000.6 5.6.7.4): written only in PREOP,
// sub-index 0 set to 0 before the entries and to their count afterwards, entries mappable in
// the PDO's direction and within the SyncManager's size. The SDO transfer protocol
// (sdo_server.hpp) moves the bytes; this decides what they may do.

#include <cstdint>
#include <span>
#include <vector>

#include "esi/ethercat/sync_manager_type.hpp"
#include "sim/coe_dictionary.hpp"

namespace esi::sim {

// What an SM carries, numbered as 0x1C00 and the SII number it: the protocol layer's.
using SmRole = ethercat::SyncManagerType;

struct AccessRules {
    bool complete_access = false;  // CoE@CompleteAccess
    std::vector<SmRole> sm_roles;  // by SM number
    // Largest process data per SM in bits (the SM's MaxSize, else what the ESC's process RAM
    // holds in three buffers); by SM number.
    std::vector<std::uint32_t> sm_max_bits;
};

class ObjectAccess {
public:
    ObjectAccess(CoeDictionary& dictionary, AccessRules rules) : dictionary_(dictionary), rules_(std::move(rules)) {}

    // An abort code (sdo_abort.hpp), or none with the bytes in `out`. Complete access starts at
    // sub-index 0 or 1 and returns the whole object's stream from there.
    [[nodiscard]] std::uint32_t read(std::uint16_t index, std::uint8_t subindex, bool complete, AlState state,
                                     std::vector<std::uint8_t>& out) const;
    [[nodiscard]] std::uint32_t write(std::uint16_t index, std::uint8_t subindex, bool complete, AlState state,
                                      std::span<const std::uint8_t> data);
    // The most bytes a download to this target can carry; a larger announced size is refused
    // before any of it is buffered. 0 when the target does not exist.
    [[nodiscard]] std::size_t write_limit(std::uint16_t index, std::uint8_t subindex, bool complete) const;

    [[nodiscard]] const AccessRules& rules() const { return rules_; }
    [[nodiscard]] CoeDictionary& dictionary() { return dictionary_; }

private:
    [[nodiscard]] std::uint32_t write_entry(CoeObject& object, CoeEntry& entry, AlState state,
                                            std::span<const std::uint8_t> data, bool check_access);
    [[nodiscard]] std::uint32_t check_pdo_object_write(const CoeObject& object, const CoeEntry& entry,
                                                       std::uint64_t value) const;
    [[nodiscard]] std::uint32_t check_mapping_entry(std::uint16_t mapping_index, std::uint32_t mapped) const;
    [[nodiscard]] std::uint32_t check_mapping_complete(const CoeObject& mapping, std::uint8_t count) const;
    [[nodiscard]] std::uint32_t check_assignment_complete(const CoeObject& assignment, std::uint8_t count) const;

    CoeDictionary& dictionary_;
    AccessRules rules_;
};

// PDO objects by index range (ETG.1000.6 5.6.7.4.7 and .9).
[[nodiscard]] bool is_rx_mapping(std::uint32_t index);
[[nodiscard]] bool is_tx_mapping(std::uint32_t index);
[[nodiscard]] bool is_assignment(std::uint32_t index);
// Bits a mapping object maps with its first `count` entries (0 when an entry names nothing).
[[nodiscard]] std::uint32_t mapped_bits(const CoeObject& mapping, std::uint8_t count);

}  // namespace esi::sim
