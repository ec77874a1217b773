// One device with esi-net's defaults (esi/net/default_slave.hpp): the steps of network_build.cpp
// for a slave spec that states nothing but the device.

#include "esi/net/default_slave.hpp"

#include "slave_context.hpp"

namespace esi::net {

DefaultSlave configure_default_slave(const EtherCATInfo& info, const Device& device, Diagnostics& diagnostics) {
    DefaultSlave out;
    const NetworkSpec network;
    const SlaveSpec spec;
    NetworkSlave& slave = out.slave;
    slave.device = &device;
    slave.info = &info;
    slave.vendor_id = info.vendor ? info.vendor->id.value_or(0) : 0;
    slave.product_code = device.type.product_code.value_or(0);
    slave.revision = device.type.revision_no.value_or(0);
    SlaveContext context{network, spec, slave, device, info, Limits{}, diagnostics};
    configure_modules(context);
    select_pdos(context);
    configure_pdo_entries(context);
    setup_sync_managers(context);
    for (std::size_t i = 0; i < slave.modules.size(); ++i) {
        const Module& module = *slave.modules[i].module;
        if (!module.profile || !module.profile->dictionary) continue;
        const Dictionary& dictionary = *module.profile->dictionary;
        for (const Object& object : dictionary.objects)
            out.module_objects.push_back(
                {slot_index(context, i, object.index, object.index_depend_on_slot.value_or(false)), &object, &dictionary});
    }
    return out;
}

}  // namespace esi::net
