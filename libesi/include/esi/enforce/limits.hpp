#pragma once
// The limits a generated device is held to (docs/codegen.md, "Limits"). esi-gen writes nothing for
// a device that breaks them. Each device is checked by the profile-* rules, the rules esi-lint
// runs for a vendor constraint profile, against
//   - the limits of an .esi-lint.yaml named explicitly (esi-gen --config), resolved for the source
//     file the way esi-lint resolves them (extends, overrides by file glob and product code), and
//   - on top of those, field by field, the limits the device's own source declares
//     (`devices[].limits`), as an override scoped to that device would be.
// The config's `rules:` grade the profile-* rules (off, info, warning, error); esi-lint's other
// rules do not run here. No config is looked up by directory: a build's outputs depend only on
// the inputs it names.

#include <filesystem>
#include <optional>

#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/load/document.hpp"

namespace esi {

struct LimitsOptions {
    std::optional<std::filesystem::path> config;  // an .esi-lint.yaml profile
    std::optional<DeviceSelector> device;         // only the devices it selects (esi-gen --device)
};

// The profile-* findings with the source's positions, sorted, after the config's own problems
// (with the config's path and positions). A finding at error severity, or an unusable config,
// means the device must not be generated.
[[nodiscard]] Diagnostics enforce_limits(const LoadedDocument& loaded, const LimitsOptions& options);

}  // namespace esi
