#pragma once
// The view of a whole document, kept apart per device so that per-device templates can render
// each device without the others.

#include <memory>
#include <vector>

#include "codegen/view_parts.hpp"
#include "esi/codegen/model_view.hpp"

namespace esi::codegen {

struct DeviceViewEntry {
    const EtherCATInfo* info = nullptr;
    const Device* device = nullptr;
    std::string c_name;
    ViewValue view;  // in the DocumentView's arena
};

struct DocumentView {
    std::unique_ptr<ViewArena> arena = std::make_unique<ViewArena>();  // holds every value below
    ViewValue root;  // view_version, generator, source_file, vendor (no devices)
    std::vector<DeviceViewEntry> devices;
    Diagnostics diagnostics;
};

// The devices `options` selects, in document order, with their unique c_name.
[[nodiscard]] std::vector<DeviceViewEntry> selected_devices(const EsiDocument& document, const ViewOptions& options);

[[nodiscard]] DocumentView build_document_view(const EsiDocument& document, const ViewOptions& options);

// The document view as --dump-model prints it: the root fields plus "devices".
[[nodiscard]] ViewValue document_value(DocumentView& view);

// What a per-device template sees: the root fields plus "device".
[[nodiscard]] ViewValue device_context(DocumentView& view, const DeviceViewEntry& device);

}  // namespace esi::codegen
