#pragma once
// --device PRODUCTCODE[:REVISION]: each part decimal, #x… or 0x… hex.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/model/device.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

struct DeviceSelector {
    std::uint32_t product_code = 0;
    std::optional<std::uint32_t> revision;

    [[nodiscard]] bool matches(const Device& device) const;
};

// nullopt and a message in `error` when the text is not PRODUCTCODE[:REVISION].
[[nodiscard]] std::optional<DeviceSelector> parse_device_selector(std::string_view text, std::string& error);

// The devices of a document a selector picks (all devices when no selector is given).
[[nodiscard]] std::vector<const Device*> select_devices(const EsiDocument& document, const std::optional<DeviceSelector>& selector);

}  // namespace esi
