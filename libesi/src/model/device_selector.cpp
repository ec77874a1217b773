#include "esi/device_selector.hpp"

#include "esi/number.hpp"

namespace esi {

bool DeviceSelector::matches(const Device& device) const {
    if (device.type.product_code != product_code) return false;
    return !revision || device.type.revision_no == *revision;
}

std::optional<DeviceSelector> parse_device_selector(std::string_view text, std::string& error) {
    const auto colon = text.find(':');
    auto part = [&](std::string_view s, std::string_view what) -> std::optional<std::uint32_t> {
        const ParsedNumber n = parse_number(s);
        if (!n.ok() || n.value.negative || n.value.magnitude > 0xFFFFFFFFu) {
            error = std::string(what) + " '" + std::string(trim(s)) + "' is not a number (decimal, #x… or 0x…) up to 0xFFFFFFFF";
            return std::nullopt;
        }
        return static_cast<std::uint32_t>(n.value.magnitude);
    };
    DeviceSelector selector;
    const auto code = part(text.substr(0, colon), "product code");
    if (!code) return std::nullopt;
    selector.product_code = *code;
    if (colon != std::string_view::npos) {
        const auto revision = part(text.substr(colon + 1), "revision");
        if (!revision) return std::nullopt;
        selector.revision = revision;
    }
    return selector;
}

std::vector<const Device*> select_devices(const EsiDocument& document, const std::optional<DeviceSelector>& selector) {
    std::vector<const Device*> out;
    for (const auto& info : document.infos)
        for (const auto& device : info.devices)
            if (!selector || selector->matches(device)) out.push_back(&device);
    return out;
}

}  // namespace esi
