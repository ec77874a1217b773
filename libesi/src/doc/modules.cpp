#include "doc/modules.hpp"

namespace esi::doc {

bool slot_accepts(const Slot& slot, const Module& module) {
    for (const auto& ident : slot.module_idents)
        if (ident.value == module.module_ident) return true;
    if (module.module_class)
        for (const auto& c : slot.module_classes)
            if (c.class_name == *module.module_class) return true;
    return false;
}

std::vector<std::size_t> accepted_modules(const EtherCATInfo& info, const Device& device) {
    std::vector<std::size_t> out;
    if (!device.slots) return out;
    for (std::size_t m = 0; m < info.modules.size(); ++m)
        for (const Slot& slot : device.slots->slots)
            if (slot_accepts(slot, info.modules[m])) {
                out.push_back(m);
                break;
            }
    return out;
}

}  // namespace esi::doc
