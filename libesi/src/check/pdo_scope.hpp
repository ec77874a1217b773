#pragma once
// The places PDOs are declared, devices and modules, with what the pdo-… rules need to check
// them: the owner's SyncManagers and the Dictionary its entries refer to.

#include <vector>

#include "esi/model/ethercat_info.hpp"

namespace esi::rules {

struct PdoScope {
    const Device* device = nullptr;  // null for a module
    const Module* module = nullptr;  // null for a device
    const std::vector<Pdo>* rx_pdos = nullptr;
    const std::vector<Pdo>* tx_pdos = nullptr;
    const Dictionary* dictionary = nullptr;  // the owner's own Dictionary, if it has one
    // True when every object a PDO entry names must be in `dictionary`: a device without Slots
    // whose Dictionary lists objects. Modules and modular devices take objects from module
    // descriptions and slot-dependent indices (ETG.2000 Modules/Slots), so there an object the
    // Dictionary does not list proves nothing.
    bool dictionary_is_complete = false;

    template <class F>
    void for_each_pdo(F&& f) const {
        for (const auto& pdo : *rx_pdos) f(pdo);
        for (const auto& pdo : *tx_pdos) f(pdo);
    }
};

// Every device and module of the document, in document order.
[[nodiscard]] std::vector<PdoScope> pdo_scopes(const EsiDocument& document);

// Whether an entry's index is relative to its slot (ETG.2000 DependOnSlot/DependOnSlotGroup):
// the real index is only known once a module sits in a slot.
[[nodiscard]] bool depends_on_slot(const PdoEntry& entry);
[[nodiscard]] bool depends_on_slot(const Pdo& pdo);

}  // namespace esi::rules
