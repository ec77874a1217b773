#pragma once
// One device configured as esi-net configures a slave that NETWORK.yaml names without options:
// the modules esi-net places in its slots by default (ETG.2001: the Default module of every
// slot that needs one, MinInstances), the default PDO assignment with the slot
// increments applied to PDO and entry indices, and the objects the modules bring, at their
// indices in the slot. For users that run one device from its model (esi-sim's model slave).

#include <cstdint>
#include <optional>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

struct ModuleObject {
    std::uint32_t index = 0;  // after the slot's index increment
    const Object* object = nullptr;
    const Dictionary* dictionary = nullptr;  // the module's, for the object's DataTypes
};

struct DefaultSlave {
    NetworkSlave slave;  // modules, pdos and sms as esi-net sets them up
    std::vector<ModuleObject> module_objects;
};

// `device` is one of info.devices. Problems go to `diagnostics` (path empty: no network file).
[[nodiscard]] DefaultSlave configure_default_slave(const EtherCATInfo& info, const Device& device, Diagnostics& diagnostics);

}  // namespace esi::net
