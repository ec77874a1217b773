#pragma once
// A modular device with the modules of its slots, as the one Device its firmware serves: the
// device's own PDOs and objects, then each module's PDOs and objects with their indexes moved by
// the slot's increments (ETG.2000 Slots; ETG.2001), in the PDOs esi-net assigned to the slave.
// The result has no slots left: its modules are placed (the model slave places a device's
// default modules itself when it still has slots).

#include "esi/model/device.hpp"
#include "esi/net/network.hpp"

namespace esi::sim {

[[nodiscard]] Device device_with_modules(const net::NetworkSlave& slave);

}  // namespace esi::sim
