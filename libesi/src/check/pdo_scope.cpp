#include "check/pdo_scope.hpp"

namespace esi::rules {

std::vector<PdoScope> pdo_scopes(const EsiDocument& document) {
    std::vector<PdoScope> out;
    std::size_t count = 0;
    for (const auto& info : document.infos) count += info.devices.size() + info.modules.size();
    out.reserve(count);  // every pdo rule starts with this list: one allocation for it
    for (const auto& info : document.infos) {
        for (const auto& device : info.devices) {
            PdoScope scope;
            scope.device = &device;
            scope.rx_pdos = &device.rx_pdos;
            scope.tx_pdos = &device.tx_pdos;
            scope.dictionary = device.dictionary();
            scope.dictionary_is_complete = scope.dictionary && !scope.dictionary->objects.empty() && !device.slots;
            out.push_back(scope);
        }
        for (const auto& module : info.modules) {
            PdoScope scope;
            scope.module = &module;
            scope.rx_pdos = &module.rx_pdos;
            scope.tx_pdos = &module.tx_pdos;
            scope.dictionary = module.profile && module.profile->dictionary ? &*module.profile->dictionary : nullptr;
            out.push_back(scope);
        }
    }
    return out;
}

bool depends_on_slot(const PdoEntry& entry) {
    return entry.index_depend_on_slot.value_or(false) || entry.index_depend_on_slot_group.value_or(false);
}

bool depends_on_slot(const Pdo& pdo) {
    return pdo.index_depend_on_slot.value_or(false) || pdo.index_depend_on_slot_group.value_or(false);
}

}  // namespace esi::rules
