#pragma once
// `esi-net init --from-igh`: a NETWORK.yaml from a live bus scan, the output of the IgH
// master's `ethercat slaves -v` — the starting point lcec_configgen and `ethercat cstruct` use,
// turned into a network file that builds from ESI files instead of from the bus.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/library_index.hpp"

namespace esi::net {

struct ScannedSlave {
    std::uint32_t master = 0;
    std::uint32_t position = 0;
    std::optional<std::uint16_t> alias;
    std::optional<std::uint32_t> vendor_id;
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision;
    std::optional<std::uint32_t> serial;
    std::string device_name;   // General/Device name
    std::string order_number;  // General/Order number
    SourcePos pos;             // the "=== Master m, Slave n ===" line
};

struct IghScan {
    std::string path;
    std::vector<ScannedSlave> slaves;  // of the first master in the text, in bus order
    Diagnostics diagnostics;
};

// Reads the blocks "=== Master m, Slave n ===" and their Identity, Alias and General lines;
// other lines are skipped. A block without a vendor id or product code is an error.
[[nodiscard]] IghScan parse_igh_slaves(std::string_view text, const std::string& path);

struct InitOptions {
    std::vector<std::string> esi;  // written to the network's `esi:` as given
    std::uint32_t cycle_time_us = 1000;
};

struct InitResult {
    std::string yaml;
    Diagnostics diagnostics;  // a warning per device the library does not describe
};

// The network: one slave per scanned device, named D1, D2 … as lcec_configgen names them,
// identified by vendor id, product code and revision; with an index, each slave's comment
// names the ESI device (or says that none was found).
[[nodiscard]] InitResult network_from_scan(const IghScan& scan, const LibraryIndex* index, const InitOptions& options);

}  // namespace esi::net
