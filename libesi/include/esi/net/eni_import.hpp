#pragma once
// `esi-net init --from-eni`: a NETWORK.yaml from an ENI (ETG.2100) that TwinCAT, EC-Engineer or
// esi-net wrote, so that `esi-net build` regenerates the same per-slave content from the ESI
// files — and from there the IgH, lcec and ROS 2 outputs — instead of keeping the export.
//
// The ENI says what was configured; the network file says only what the ESI does not imply.
// So each slave is first built from its identity alone, and what differs from the ENI is added:
// the PDO assignment (`pdos`), the entries of remapped PDOs (`pdo_entries`), the DC op mode whose
// AssignActivate the ENI writes (`dc`), and every CoE start-up command the ESI does not already
// produce (`sdos`, raw data, transitions, complete access). The master's name and cycle time
// come from Config/Master/Info/Name and Config/Cyclic/CycleTime.

#include <string>
#include <string_view>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/library_index.hpp"

namespace esi::net {

struct EniImportOptions {
    std::vector<std::string> esi;  // written to the network's `esi:` as given
    // Slaves no ESI of the library describes are written as comments instead of slaves (the
    // network then builds, with every later slave one position earlier). Default: kept, so
    // positions stay, and `build` names the missing ESI.
    bool omit_unknown = false;
};

struct EniImport {
    std::string yaml;         // empty when the ENI cannot be read
    std::vector<std::size_t> written;  // for each slave of the network, its position in the ENI
    Diagnostics diagnostics;  // errors: not an ENI, encrypted; warnings: what the file cannot say
};

[[nodiscard]] EniImport network_from_eni(std::string_view xml, const std::string& path, const LibraryIndex& index,
                                         const EniImportOptions& options);

}  // namespace esi::net
