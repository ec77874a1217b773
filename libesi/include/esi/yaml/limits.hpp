#pragma once
// The `limits:` mapping: a device family's own constraints (docs/lint-config.md), read the same
// way wherever it is written — in a device source (`devices[].limits`) and in .esi-lint.yaml
// (`limits`, `overrides[].limits`) — with the same keys, messages and positions.
//
//   limits:
//     max_pdos: { rx: 4, tx: 4 }           # or one number for both
//     pdo_index_ranges: { rx: ["0x1600-0x1603"], tx: [[0x1A00, 0x1A03]] }
//     max_entries_per_pdo: 6
//     bitlen: [8, 16, 32]
//     fixed_sm: { 2: Outputs, 3: Inputs }
//     transitions: [PS, SO]
//     max_init_cmd_bytes: 4
//     max_mailbox_size: 128
//     absent_objects: [0x1008]
//     mailbox_protocols: [CoE, VoE]
//     max_fmmus: 4
//     max_sms: 6
//     pdo_assign: false
//     pdo_config: false
//     pdo_names: { rx: Outputs, tx: Inputs }
//     parameter_index: { base: 0x2000, group_size: 0x200, groups: A-Z }
//     sync0_cycle: { min_ns: 1000000, multiple_of_ns: 1000000, factors: [1, 2] }

#include "esi/model/limits.hpp"
#include "esi/yaml/reader.hpp"

namespace esi::yaml {

// Problems go to the reader's diagnostics; what could be read is returned.
[[nodiscard]] Limits read_limits(Reader& reader, const Node& node);

}  // namespace esi::yaml
