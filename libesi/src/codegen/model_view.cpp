#include <filesystem>

#include "codegen/document_view.hpp"
#include "esi/codegen/identifier.hpp"
#include "codegen/values.hpp"
#include "codegen/view_json.hpp"

namespace esi::codegen {

std::vector<DeviceViewEntry> selected_devices(const EsiDocument& document, const ViewOptions& options) {
    std::vector<DeviceViewEntry> out;
    IdentifierScope device_scope;
    for (const EtherCATInfo& info : document.infos) {
        for (const Device& device : info.devices) {
            if (options.device && !options.device->matches(device)) continue;
            DeviceViewEntry entry;
            entry.info = &info;
            entry.device = &device;
            const std::string base = c_identifier(device.type.text.empty() ? primary_text(device.names) : device.type.text, "device");
            // Revisions of one product share a Type text; the revision tells them apart.
            entry.c_name = device_scope.claim(base, "r" + hex(device.type.revision_no.value_or(0), 8).substr(2));
            out.push_back(std::move(entry));
        }
    }
    return out;
}

DocumentView build_document_view(const EsiDocument& document, const ViewOptions& options) {
    DocumentView out;
    ViewArena& arena = *out.arena;
    ViewContext context{document.path, &out.diagnostics, &arena};

    ObjectBuilder root(arena);
    root.add("view_version", model_view_version);
    root.add("generator", ViewValue::of_static("esi-gen"));
    // The file name only: the same source gives the same output wherever it is checked out.
    root.add("source_file", std::filesystem::path(document.path).filename().string());
    root.add("vendor", document.infos.empty() ? vendor_view(EtherCATInfo{}, arena) : vendor_view(document.infos.front(), arena));
    out.root = root.finish();

    out.devices = selected_devices(document, options);
    for (auto& entry : out.devices) {
        const std::string prefix = options.symbol_prefix ? c_identifier(*options.symbol_prefix, "esi") : entry.c_name;
        entry.view = device_view(*entry.info, *entry.device, entry.c_name, prefix, context);
    }
    if (out.devices.empty()) {
        out.diagnostics.emplace(Severity::error, "codegen-no-device",
                                options.device ? "no device matches the --device selection" : "the source describes no device",
                                document.path, document.root_pos);
    }
    return out;
}

ViewValue document_value(DocumentView& view) {
    ObjectBuilder j(*view.arena);
    j.add_members_of(view.root);
    j.add("device_count", view.devices.size());
    ListBuilder devices(*view.arena);
    for (const auto& d : view.devices) devices.add(d.view);
    j.add("devices", devices.finish());
    return j.finish();
}

ViewValue device_context(DocumentView& view, const DeviceViewEntry& device) {
    ObjectBuilder j(*view.arena);
    j.add_members_of(view.root);
    j.add("device", device.view);
    return j.finish();
}

ModelViewText model_view_json(const EsiDocument& document, const ViewOptions& options) {
    DocumentView view = build_document_view(document, options);
    ModelViewText out;
    // Strings from DefaultData may hold any bytes: invalid UTF-8 is replaced, never thrown about.
    out.json = to_json(document_value(view)).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
    out.diagnostics = std::move(view.diagnostics);
    return out;
}

}  // namespace esi::codegen
