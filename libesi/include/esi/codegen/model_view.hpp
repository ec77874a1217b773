#pragma once
// The one JSON view of a document that every code template renders from (documented field by
// field in docs/codegen.md; `esi-gen --dump-model json` prints it). It is built from the model
// only, so YAML sources and ESI files give the same view for the same device.

#include <optional>
#include <string>

#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::codegen {

// Bumped whenever a field changes meaning or disappears (templates may check it).
inline constexpr int model_view_version = 1;

struct ViewOptions {
    std::optional<DeviceSelector> device;        // only the devices it matches; all when absent
    std::optional<std::string> symbol_prefix;    // C symbol prefix; default: each device's c_name
};

struct ModelViewText {
    std::string json;  // pretty-printed (2 spaces), keys in documented order, ends with a newline
    Diagnostics diagnostics;  // warnings about what the view leaves out; an error if no device matches
};

[[nodiscard]] ModelViewText model_view_json(const EsiDocument& document, const ViewOptions& options = {});

}  // namespace esi::codegen
