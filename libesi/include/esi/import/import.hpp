#pragma once
// esi-gen --import as a library: an ESI model -> the YAML device source (docs/yaml-format.md,
// docs/yaml-import.md). Loading the text again with load_device_source() gives a model that
// esi-diff finds identical to the input: what derivation reproduces exactly (SyncManagers, FMMUs,
// 0x1000, 0x1018, 0x16xx/0x1Axx, 0x1C00, 0x1C12/0x1C13, DataTypes, PDO entry details …) is left
// out, checked by deriving it; what the file has differently stays explicit with derivation
// switched off for that part. Unmodelled XML goes through the `xml` escape hatch. Deterministic.

#include <optional>
#include <string>

#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

struct ImportOptions {
    // Only the devices this selects (modules, groups and the vendor are kept).
    std::optional<DeviceSelector> device;
    // Leave out what derivation reproduces exactly (checked per device). Off: everything explicit
    // and `derive: false` on every device and module.
    bool omit_derived = true;
};

struct ImportResult {
    std::optional<std::string> yaml;  // absent when the document cannot be imported (diagnostics say why)
    // Errors (a root other than EtherCATInfo/EtherCATModule, --device matching nothing) and
    // warnings (a value the YAML format cannot express exactly, with its model path).
    Diagnostics diagnostics;
    std::size_t devices = 0;          // devices written
    std::size_t derived_devices = 0;  // devices with at least one part left to derivation
};

[[nodiscard]] ImportResult import_device_source(const EsiDocument& document, const ImportOptions& options = {});

}  // namespace esi
