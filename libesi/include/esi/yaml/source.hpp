#pragma once
// The YAML device source front end: one YAML file -> a complete, derived model (SyncManagers,
// mapping and assignment objects, 0x1C00, 0x1018 … filled in; explicit values win) plus the
// limits each device declares. Errors carry the YAML file:line:col. The format is documented in
// docs/yaml-format.md, its JSON Schema is schemas/esi-device.schema.json.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "esi/model/limits.hpp"
#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/source_text.hpp"

namespace esi {

// Bounds on hostile input, checked before any node tree is walked.
struct DeviceSourceOptions {
    std::size_t max_bytes = 16u << 20;     // file size
    std::size_t max_depth = 64;            // nesting of mappings and lists
    std::uint64_t max_nodes = 1'000'000;   // nodes after anchor/alias expansion ("billion laughs")
};

struct DeviceSource {
    std::optional<EsiDocument> document;  // absent when the source has errors
    // The limits each device declares (`limits:`), keyed by its identity.
    std::vector<std::pair<DeviceSelector, Limits>> device_limits;
    Diagnostics diagnostics;  // sorted; positions are in the YAML file
    SourceTextPtr source;     // the YAML text, for quoting lines (also document->source)
};

[[nodiscard]] DeviceSource load_device_source(std::string_view bytes, const std::string& path,
                                              const DeviceSourceOptions& options = {});
[[nodiscard]] DeviceSource load_device_source_file(const std::filesystem::path& path,
                                                   const DeviceSourceOptions& options = {});

}  // namespace esi
