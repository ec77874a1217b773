#pragma once
// `esi-net check`: a running bus (bus_dump.hpp, igh_scan.hpp, SII images) against the ESI
// library and, when given, the network file. For each slave on the bus: the ESI device of its
// identity (or the nearest ones), then its SyncManagers, FMMUs and PDO mapping as the bus has
// them against what the network (or, without one, the ESI's default configuration) says, and
// its SII against the ESI (the comparison of `esi-sii check`).
//
// Findings are diagnostics located in the dump they come from, with a rule id:
//   check-identity       the bus has another device at this position than the network names
//   check-unknown-device no ESI of the library describes the identity (notes: the nearest)
//   check-sm             a SyncManager's start address, control byte or length differs
//   check-fmmu           an FMMU maps another physical address or direction than the network's
//   check-pdo-assign     the PDOs assigned to a SyncManager differ
//   check-pdo-mapping    a PDO's entries differ
//   check-sii            the SII image differs from the ESI (the sii rule of each difference in a note)
// Against a network file a difference is an error; against the ESI's defaults a PDO difference is
// a warning (the application may configure the device otherwise).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/bus_dump.hpp"
#include "esi/net/library_index.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

struct SiiDump {
    std::size_t position = 0;
    std::vector<std::uint8_t> bytes;
    std::string path;
};

struct CheckedSlave {
    std::size_t position = 0;
    std::optional<std::uint32_t> vendor_id, product_code, revision;
    std::string name;
    std::string esi;  // "file:line" of the ESI device, empty when none
    std::size_t findings = 0;
};

struct CheckResult {
    std::vector<CheckedSlave> slaves;
    Diagnostics findings;
};

// `network`: the built network file, or nullptr to compare with each device's ESI defaults.
[[nodiscard]] CheckResult check_bus(const std::vector<BusSlave>& bus, const std::vector<SiiDump>& sii, const Network* network,
                                    const LibraryIndex& index);

// The dumps of one bus merged by position: identities from any of them, SMs, FMMUs and PDOs
// from the first dump that lists them.
[[nodiscard]] std::vector<BusSlave> merge_bus_dumps(const std::vector<std::vector<BusSlave>>& dumps);

// JSON: {"slaves": [{position, identity, esi, findings}], "findings": [{rule, severity, path, line, message, notes}]}
[[nodiscard]] std::string check_result_json(const CheckResult& result);

}  // namespace esi::net
