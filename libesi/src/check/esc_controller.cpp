#include "check/esc_controller.hpp"

#include "esi/number.hpp"

namespace esi::rules {

BlockLimit block_limit(const Device& device, std::string_view element) {
    const XmlElement* controller = device.extras.find("Info/EtherCATController");
    if (const XmlElement* stated = controller ? controller->find(element) : nullptr) {
        const ParsedNumber n = parse_number(stated->text);
        if (n.ok() && !n.value.negative && n.value.magnitude <= register_map_blocks) return {n.value.magnitude, true};
    }
    return {register_map_blocks, false};
}

std::string block_limit_reason(const BlockLimit& limit, std::string_view element, std::string_view what) {
    if (limit.stated) return "Info/EtherCATController/" + std::string(element) + " says the ESC has " + std::to_string(limit.count);
    return "the ESC register map has room for " + std::to_string(register_map_blocks) + " " + std::string(what);
}

}  // namespace esi::rules
