#pragma once
// The changes of a result grouped by device, the groups ordered most severe first (errors, then
// breaking, compatible, cosmetic), ties in the result's order: how every report (text, Markdown,
// esi-doc's HTML) presents them.

#include <string>
#include <vector>

#include "esi/diff/diff.hpp"

namespace esi {

struct DeviceGroup {
    const std::optional<DeviceRef>* device = nullptr;  // of the first change; null optional: the file
    std::vector<const Change*> changes;
    ChangeClass worst = ChangeClass::cosmetic;
    bool has_error = false;
};

[[nodiscard]] std::vector<DeviceGroup> group_by_device(const DiffResult& result);

// "'EL1008' product code #x03F03052, revision #x00100000" (or "File (vendor, groups, modules)").
[[nodiscard]] std::string device_heading(const std::optional<DeviceRef>& device);

// "3 breaking, 1 compatible, 2 cosmetic" (classes with no change left out); "no changes".
[[nodiscard]] std::string class_counts(const DiffResult& result);

}  // namespace esi
