// Placeholder until the YAML front end lands (branch "yaml").
#include "esi/yaml/source.hpp"

namespace esi {

DeviceSource load_device_source(std::string_view /*bytes*/, const std::string& path) {
    DeviceSource out;
    out.diagnostics.emplace(Severity::error, "yaml-unsupported", "YAML device sources are not supported by this build", path, {});
    return out;
}

DeviceSource load_device_source_file(const std::filesystem::path& path) { return load_device_source({}, path.string()); }

}  // namespace esi
