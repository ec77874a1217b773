#include "slotted_device.hpp"

#include <algorithm>

namespace esi::sim {

namespace {

// The index increment of the slot a module sits in (a Slot's own value, else the Slots one).
std::uint32_t slot_index_increment(const Slots& slots, std::uint32_t slot) {
    std::uint32_t increment = slots.slot_index_increment.value_or(0);
    std::uint32_t number = 0;
    for (const Slot& s : slots.slots) {
        const std::uint32_t count = std::max<std::uint32_t>(1, s.max_instances);
        if (slot < number + count) return s.slot_index_increment.value_or(increment);
        number += count;
    }
    return increment;
}

Pdo pdo_from(const net::ConfiguredPdo& configured) {
    Pdo pdo;
    pdo.direction = configured.direction;
    pdo.index = configured.index;
    pdo.names.push_back({configured.name, std::nullopt, {}});
    pdo.sm = configured.sm;
    pdo.fixed = configured.fixed;
    pdo.mandatory = configured.mandatory;
    for (const net::ConfiguredEntry& e : configured.entries) {
        PdoEntry entry;
        entry.index = e.index;
        entry.subindex = e.subindex;
        entry.bit_len = e.bit_len;
        entry.names.push_back({e.name, std::nullopt, {}});
        if (!e.data_type.empty()) entry.data_type = e.data_type;
        pdo.entries.push_back(std::move(entry));
    }
    return pdo;
}

}  // namespace

Device device_with_modules(const net::NetworkSlave& slave) {
    Device device = *slave.device;
    if (slave.modules.empty() || !device.slots) return device;
    // The PDOs: the device's own, with the assignment esi-net made, then the modules' assigned ones.
    for (std::vector<Pdo>* list : {&device.rx_pdos, &device.tx_pdos})
        for (Pdo& pdo : *list) {
            pdo.sm.reset();
            for (const net::ConfiguredPdo& configured : slave.pdos)
                if (!configured.module && configured.index == pdo.index && configured.direction == pdo.direction)
                    pdo.sm = configured.sm;
        }
    for (const net::ConfiguredPdo& configured : slave.pdos)
        if (configured.module)
            (configured.direction == PdoDirection::rx ? device.rx_pdos : device.tx_pdos).push_back(pdo_from(configured));

    // The objects: the modules' dictionaries joined to the device's, moved to their slots.
    if (device.profiles.empty()) device.profiles.emplace_back();
    Profile& profile = device.profiles.front();
    if (!profile.dictionary) profile.dictionary.emplace();
    Dictionary& dictionary = *profile.dictionary;
    for (const net::ModuleInSlot& m : slave.modules) {
        if (!m.module->profile || !m.module->profile->dictionary) continue;
        const Dictionary& module_dictionary = *m.module->profile->dictionary;
        for (const DataType& type : module_dictionary.data_types)
            if (!dictionary.find_data_type(type.name)) dictionary.data_types.push_back(type);
        const std::uint32_t increment = slot_index_increment(*device.slots, m.slot);
        for (Object object : module_dictionary.objects) {
            if (object.index_depend_on_slot.value_or(false)) object.index += m.slot * increment;
            if (dictionary.find_object(object.index)) continue;  // the device's own object wins
            dictionary.objects.push_back(std::move(object));
        }
    }
    std::sort(dictionary.objects.begin(), dictionary.objects.end(),
              [](const Object& a, const Object& b) { return a.index < b.index; });
    // The modules are in: the firmware must not add its slots' default modules on top.
    device.slots.reset();
    return device;
}

}  // namespace esi::sim
