#pragma once
// What a running bus reports, read from the text the masters' tools print, for `esi-net check`:
//
//   IgH    `ethercat slaves -v`  identities (esi/net/igh_scan.hpp reads it)
//          `ethercat pdos`       SMs (PhysAddr, DefaultSize, ControlRegister, Enable), the PDOs
//                                assigned to each and their entries
//   SOEM   `slaveinfo IF -map [-sdo]`  identities, SMs (A/L/F/Type), FMMUs (Ls/Ll/Ps/Ty) and the
//                                PDO mapping "according to CoE" or "according to SII"
//
// Lines the readers do not know are skipped (the tools print more than is compared); a block
// that cannot be read is an error located in the dump.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

struct BusEntry {
    std::uint32_t index = 0, subindex = 0, bit_len = 0;
    friend bool operator==(const BusEntry&, const BusEntry&) = default;
};

struct BusPdo {
    PdoDirection direction = PdoDirection::rx;
    std::uint32_t index = 0;
    std::string name;
    std::vector<BusEntry> entries;
};

struct BusSm {
    std::uint32_t number = 0;
    std::uint16_t start = 0;
    std::optional<std::uint16_t> length;  // SOEM: the configured length
    std::uint8_t control = 0;
    std::vector<BusPdo> pdos;
    SourcePos pos;
};

struct BusFmmu {
    std::uint32_t number = 0;
    std::uint16_t physical_start = 0;
    std::uint16_t length = 0;
    std::uint8_t type = 0;  // 1 read (inputs), 2 write (outputs), 3 both
    SourcePos pos;
};

struct BusSlave {
    std::size_t position = 0;  // 0-based, in bus order
    std::optional<std::uint32_t> vendor_id, product_code, revision;
    std::string name;
    std::vector<BusSm> sms;
    std::vector<BusFmmu> fmmus;
    bool has_mapping = false;  // the dump lists PDOs (slaveinfo without -map does not)
    std::string source;        // the dump file
    SourcePos pos;
};

struct BusDump {
    std::vector<BusSlave> slaves;
    Diagnostics diagnostics;
};

// `ethercat pdos` of one master: blocks "=== Master m, Slave n ===" (or one slave without a
// header, as `ethercat pdos -p N` prints).
[[nodiscard]] BusDump parse_igh_pdos(std::string_view text, const std::string& path);
// SOEM's slaveinfo output (`-map` for the PDOs).
[[nodiscard]] BusDump parse_soem_slaveinfo(std::string_view text, const std::string& path);
// IgH `ethercat slaves -v`: the identities only (the scan reader of `init --from-igh`).
[[nodiscard]] BusDump parse_igh_slaves_dump(std::string_view text, const std::string& path);

}  // namespace esi::net
