#pragma once
// A device family's own constraints, as its manual states them (maximum PDOs, index ranges,
// entries per PDO, allowed BitLen values, fixed SM assignment, allowed InitCmd transitions).
// Declared in .esi-lint.yaml profiles and in the YAML device source; enforced by profile-* rules.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace esi {

struct IndexRange {
    std::uint32_t first = 0;
    std::uint32_t last = 0;
    [[nodiscard]] bool contains(std::uint32_t index) const { return index >= first && index <= last; }
};

struct Limits {
    std::optional<std::uint32_t> max_rx_pdos;
    std::optional<std::uint32_t> max_tx_pdos;
    std::vector<IndexRange> rx_pdo_ranges;  // empty: any
    std::vector<IndexRange> tx_pdo_ranges;
    std::optional<std::uint32_t> max_entries_per_pdo;
    std::vector<std::uint32_t> allowed_bit_lens;      // empty: any (padding entries are exempt)
    std::map<std::uint32_t, std::string> fixed_sms;   // SM number -> MBoxOut/MBoxIn/Outputs/Inputs
    std::vector<std::string> allowed_transitions;     // empty: any valid transition
    std::optional<std::uint32_t> max_init_cmd_bytes;  // e.g. 4: "SDO transfers limited to 32 bit"
    std::optional<std::uint32_t> max_mailbox_size;    // e.g. 128 on AX58100
    std::vector<std::uint32_t> absent_objects;        // objects the device does not have (0x1008 …)

    [[nodiscard]] bool empty() const;
    // Values set in `other` replace these (used for profiles that extend others and overrides).
    void merge(const Limits& other);
};

}  // namespace esi
