#include "check/slot_places.hpp"

namespace esi::rules {

namespace {
bool accepts(const Slot& slot, const Module& module) {
    for (const auto& ident : slot.module_idents)
        if (ident.value == module.module_ident) return true;
    if (module.module_class)
        for (const auto& module_class : slot.module_classes)
            if (module_class.class_name == *module.module_class) return true;
    return false;
}
}  // namespace

std::vector<SlotPlace> slot_places(const EsiDocument& document, const Module& module) {
    std::vector<SlotPlace> out;
    for (const auto& info : document.infos)
        for (const auto& device : info.devices) {
            if (!device.slots) continue;
            const Slots& slots = *device.slots;
            std::uint32_t number = 0;
            for (const auto& slot : slots.slots) {
                // A Slot stands for at least one slot even when MaxInstances is missing or 0.
                const std::uint32_t instances = slot.max_instances ? slot.max_instances : 1;
                if (accepts(slot, module)) {
                    SlotPlace place;
                    place.device = &device;
                    place.pdo_increment = slot.slot_pdo_increment.value_or(slots.slot_pdo_increment.value_or(0));
                    place.slot_group = slot.slot_group.value_or(0);
                    place.group_pdo_increment = slot.slot_group_pdo_increment.value_or(slots.slot_group_pdo_increment.value_or(0));
                    for (std::uint32_t i = 0; i < instances; ++i) {
                        place.slot_number = number + i;
                        out.push_back(place);
                    }
                }
                number += instances;
            }
        }
    return out;
}

std::uint32_t pdo_index_in(const Pdo& pdo, const SlotPlace& place) {
    std::uint64_t index = pdo.index;
    if (pdo.index_depend_on_slot.value_or(false)) index += std::uint64_t{place.slot_number} * place.pdo_increment;
    if (pdo.index_depend_on_slot_group.value_or(false)) index += std::uint64_t{place.slot_group} * place.group_pdo_increment;
    return static_cast<std::uint32_t>(index > 0xFFFF ? 0x10000 : index);
}

}  // namespace esi::rules
