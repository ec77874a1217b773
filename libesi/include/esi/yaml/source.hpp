#pragma once
// The YAML device source front end: one YAML file -> a complete, derived model (SyncManagers,
// mapping and assignment objects, 0x1C00, 0x1018 … filled in; explicit values win) plus the
// limits each device declares. Errors carry the YAML file:line:col.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "esi/check/limits.hpp"
#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

struct DeviceSource {
    std::optional<EsiDocument> document;  // absent when the source has errors
    // The limits each device declares (`limits:`), keyed by its identity.
    std::vector<std::pair<DeviceSelector, Limits>> device_limits;
    Diagnostics diagnostics;
};

[[nodiscard]] DeviceSource load_device_source(std::string_view bytes, const std::string& path);
[[nodiscard]] DeviceSource load_device_source_file(const std::filesystem::path& path);

}  // namespace esi
