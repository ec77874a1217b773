#pragma once
// Which modules of a catalogue a modular device's slots accept (ETG.2001): a slot names modules by
// ModuleIdent or by ModuleClass.

#include <vector>

#include "esi/model/ethercat_info.hpp"

namespace esi::doc {

[[nodiscard]] bool slot_accepts(const Slot& slot, const Module& module);

// Positions in `info.modules` of the modules some slot of `device` accepts, in file order.
[[nodiscard]] std::vector<std::size_t> accepted_modules(const EtherCATInfo& info, const Device& device);

}  // namespace esi::doc
