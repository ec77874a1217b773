#pragma once
// A device family's own constraints, as its manual states them (maximum PDOs, index ranges,
// entries per PDO, allowed BitLen values, fixed SM assignment, allowed InitCmd transitions,
// mailbox protocols, ESC resources, parameter addressing, SYNC0 cycle).
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
    friend bool operator==(const IndexRange&, const IndexRange&) = default;
};

// Manufacturer parameters addressed by a group letter and a line number ("A180", "E08"), each
// group a block of `group_size` indices from `base`: index = base + group_size × (group −
// first_group) + line. STÖBER: 0x2000 + 0x200 × (group − A) + line for A-Z.
struct ParameterIndexRule {
    std::uint32_t base = 0;
    std::uint32_t group_size = 0;  // > 0; also the bound of the line number
    char first_group = 'A';
    char last_group = 'Z';

    // nullopt when the group is not one of the rule's or the line does not fit its group.
    [[nodiscard]] std::optional<std::uint32_t> index_of(char group, std::uint32_t line) const;
    // The first index after the last group.
    [[nodiscard]] std::uint64_t end() const;
    friend bool operator==(const ParameterIndexRule&, const ParameterIndexRule&) = default;
};

// What a device accepts as its SYNC0 cycle. Only what an ESI states can be checked: an explicit
// CycleTimeSync0 value, and the Factor of an op mode whose SYNC0 cycle is the Sync unit cycle
// times (or divided by) that factor; the master's cycle itself is not in the ESI.
struct Sync0CycleRule {
    std::optional<std::uint64_t> min_ns;
    std::optional<std::uint64_t> multiple_of_ns;  // > 0
    std::vector<std::int32_t> factors;             // empty: any Factor
    friend bool operator==(const Sync0CycleRule&, const Sync0CycleRule&) = default;
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
    std::vector<std::string> mailbox_protocols;       // empty: any; else of AoE, EoE, CoE, FoE, SoE, VoE
    std::optional<std::uint32_t> max_fmmus;           // the ESC's FMMUs (ESC20: 4)
    std::optional<std::uint32_t> max_sms;             // the ESC's SyncManagers (ESC20: 6)
    // false: the master must not download the PDO assignment (0x1C12/0x1C13) or the PDO mapping
    // (0x16xx/0x1Axx), because the device configures them itself; true states no constraint.
    std::optional<bool> pdo_assign;
    std::optional<bool> pdo_config;
    std::optional<std::string> rx_pdo_name;  // the Name every RxPdo must have ("Outputs")
    std::optional<std::string> tx_pdo_name;
    std::optional<ParameterIndexRule> parameter_index;
    std::optional<Sync0CycleRule> sync0_cycle;

    [[nodiscard]] bool empty() const;
    // Values set in `other` replace these (used for profiles that extend others and overrides).
    void merge(const Limits& other);
    friend bool operator==(const Limits&, const Limits&) = default;
};

}  // namespace esi
