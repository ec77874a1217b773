#include "esi/diff/device_groups.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "esi/diff/classification.hpp"
#include "esi/number.hpp"

namespace esi {

std::vector<DeviceGroup> group_by_device(const DiffResult& result) {
    std::vector<DeviceGroup> groups;
    for (const auto& c : result.changes) {
        if (groups.empty() || *groups.back().device != c.device) {
            groups.emplace_back();
            groups.back().device = &c.device;
        }
        DeviceGroup& g = groups.back();
        g.changes.push_back(&c);
        g.worst = std::max(g.worst, c.change_class);
        g.has_error = g.has_error || is_error(c.kind);
    }
    std::stable_sort(groups.begin(), groups.end(), [](const DeviceGroup& a, const DeviceGroup& b) {
        if (a.has_error != b.has_error) return a.has_error;
        return a.worst > b.worst;
    });
    return groups;
}

std::string device_heading(const std::optional<DeviceRef>& device) {
    if (!device) return "File (vendor, groups, modules)";
    std::string out = fmt::format("'{}'", device->name);
    if (!device->type.empty() && device->type != device->name) out += fmt::format(" ({})", device->type);
    if (device->product_code) out += fmt::format(" product code {}", format_hex(*device->product_code, 8));
    if (device->revision) out += fmt::format(", revision {}", format_hex(*device->revision, 8));
    if (device->compared_revision) out += fmt::format(" (compared with revision {})", format_hex(*device->compared_revision, 8));
    return out;
}

std::string class_counts(const DiffResult& result) {
    std::vector<std::string> parts;
    for (ChangeClass c : {ChangeClass::breaking, ChangeClass::compatible, ChangeClass::cosmetic}) {
        const std::size_t n = result.count(c);
        if (n) parts.push_back(fmt::format("{} {}", n, to_string(c)));
    }
    if (parts.empty()) return "no changes";
    std::string out;
    for (const auto& p : parts) out += (out.empty() ? "" : ", ") + p;
    return out;
}

}  // namespace esi
