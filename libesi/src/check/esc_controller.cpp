#include "check/esc_controller.hpp"

#include "esi/number.hpp"

namespace esi::rules {

BlockLimit block_limit(const Device& device, std::string_view element, std::string_view what) {
    const XmlElement* stated = device.extras.find("Info/EtherCATController/" + std::string(element));
    if (stated) {
        const ParsedNumber n = parse_number(stated->text);
        if (n.ok() && !n.value.negative && n.value.magnitude <= register_map_blocks)
            return {n.value.magnitude, "Info/EtherCATController/" + std::string(element) + " says the ESC has " +
                                           std::to_string(n.value.magnitude)};
    }
    return {register_map_blocks, "the ESC register map has room for " + std::to_string(register_map_blocks) + " " + std::string(what)};
}

}  // namespace esi::rules
