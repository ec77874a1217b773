#pragma once
// Helpers for the YAML device source tests.

#include <string>

#include "esi/model/object_layout.hpp"
#include "esi/yaml/source.hpp"
#include "support/test_support.hpp"

namespace esi::test {

inline std::filesystem::path sample_path(const std::string& name) { return source_dir() / "samples" / name; }

inline DeviceSource load_yaml(const std::string& text, const std::string& path = "device.yaml",
                              const DeviceSourceOptions& options = {}) {
    return load_device_source(text, path, options);
}

// "line:col rule: message" per diagnostic, for failure messages and exact-position checks.
inline std::string describe(const Diagnostics& diagnostics) {
    std::string out;
    for (const auto& d : diagnostics)
        out += std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + std::string(to_string(d.severity)) + " " +
               d.rule + ": " + d.message + "\n";
    return out;
}

inline const Device& only_device(const DeviceSource& source) { return source.document->infos.at(0).devices.at(0); }

inline const ObjectEntry* object_entry(const Device& device, std::uint32_t index, std::uint32_t subindex,
                                       ObjectLayout& storage) {
    const Dictionary* d = device.dictionary();
    if (!d) return nullptr;
    const Object* o = d->find_object(index);
    if (!o) return nullptr;
    storage = layout_of(d, *o);
    return storage.entry(subindex);
}

// The default value of an object entry as an unsigned number (DefaultValue), if any.
inline std::optional<std::uint64_t> default_of(const Device& device, std::uint32_t index, std::uint32_t subindex) {
    ObjectLayout layout;
    const ObjectEntry* e = object_entry(device, index, subindex, layout);
    if (!e || !e->info || !e->info->default_value) return std::nullopt;
    return e->info->default_value->as_uint64();
}

}  // namespace esi::test
