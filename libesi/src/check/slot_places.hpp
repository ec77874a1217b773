#pragma once
// Where a module can sit: the Slots of the document's devices that accept it, and the PDO index
// a slot-dependent PDO gets there. ETG.2000 Slots: a Slot element stands for MaxInstances
// consecutive slots, numbered from 0 across the device; a PDO index marked DependOnSlot is
// incremented by SlotPdoIncrement (the Slot's own, else the Slots element's) per slot number, one
// marked DependOnSlotGroup by SlotGroupPdoIncrement per slot group.

#include <cstdint>
#include <optional>
#include <vector>

#include "esi/model/ethercat_info.hpp"

namespace esi::rules {

struct SlotPlace {
    const Device* device = nullptr;
    std::uint32_t slot_number = 0;
    std::uint32_t pdo_increment = 0;
    std::uint32_t slot_group = 0;
    std::uint32_t group_pdo_increment = 0;
};

// Every slot of every device of the document that accepts the module (by ModuleIdent or by
// ModuleClass); empty when the module is described alone (an EtherCATModule file).
[[nodiscard]] std::vector<SlotPlace> slot_places(const EsiDocument& document, const Module& module);

// The index `pdo` has in that slot.
[[nodiscard]] std::uint32_t pdo_index_in(const Pdo& pdo, const SlotPlace& place);

}  // namespace esi::rules
