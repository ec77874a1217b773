// derive_device(): runs the derivation steps in dependency order. Objects first (so PDO entries
// and InitCmds can name 0x1018 & co.), then entries (their sizes feed the SMs), then SMs (their
// numbers feed the assignment and 0x1C00), then the objects that describe PDOs and SMs, then
// typed InitCmd data, and last the DataTypes every object names.

#include <algorithm>
#include <cstdio>

#include "derive/steps.hpp"

namespace esi {

DeriveOptions DeriveOptions::none() {
    DeriveOptions o;
    o.groups = o.mailbox = o.sync_managers = o.fmmus = o.pdo_assignment = o.pdo_entries = o.mapping_objects =
        o.assignment_objects = o.sm_types_object = o.identity_object = o.device_type_object = o.data_types = false;
    return o;
}

namespace derive {

std::string hex4(std::uint32_t value) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "0x%04X", value);
    return buffer;
}

Dictionary* dictionary_of(Device& device, bool create) {
    for (auto& p : device.profiles)
        if (p.dictionary) return &*p.dictionary;
    if (!create) return nullptr;
    if (device.profiles.empty()) {
        Profile p;
        p.pos = device.pos;
        device.profiles.push_back(std::move(p));
    }
    Dictionary d;
    d.pos = device.profiles.front().pos;
    device.profiles.front().dictionary = std::move(d);
    return &*device.profiles.front().dictionary;
}

std::map<std::uint32_t, const Object*> object_index(const Dictionary& dictionary) {
    std::map<std::uint32_t, const Object*> out;
    for (const auto& o : dictionary.objects) out.emplace(o.index, &o);
    return out;
}

void sort_objects(Dictionary& dictionary) {
    auto& objects = dictionary.objects;
    const auto by_index = [](const Object& a, const Object& b) { return a.index < b.index; };
    if (std::is_sorted(objects.begin(), objects.end(), by_index)) return;
    // Objects are large: sort their positions, then move each object once.
    std::vector<std::size_t> order(objects.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return objects[a].index < objects[b].index; });
    std::vector<Object> sorted;
    sorted.reserve(objects.size());
    for (std::size_t i : order) sorted.push_back(std::move(objects[i]));
    objects = std::move(sorted);
}

}  // namespace derive

void derive_device(Device& device, const DeviceIntent& intent, const std::string& path, Diagnostics& diagnostics) {
    using namespace derive;
    Context context(path, diagnostics);
    const DeriveOptions& o = intent.options;

    if (o.mailbox && device.mailbox && !device.mailbox->data_link_layer) device.mailbox->data_link_layer = true;

    // A CoE device gets a dictionary for the derived objects; with those switched off (an imported
    // ESI without Dictionary) none is added, so the device stays as it was.
    const bool has_coe = device.mailbox && device.mailbox->coe;
    const bool derives_objects = o.device_type_object || o.identity_object || o.mapping_objects || o.assignment_objects ||
                                 o.sm_types_object;
    if (has_coe && derives_objects) dictionary_of(device, true);
    derive_standard_objects(device, intent, context);

    if (o.pdo_entries) {
        const Dictionary* dictionary = dictionary_of(device, false);
        derive_pdo_entries(device.rx_pdos, dictionary, context);
        derive_pdo_entries(device.tx_pdos, dictionary, context);
    }
    if (o.pdo_assignment) derive_pdo_assignment(device, intent, plan_sms(device, intent), context);
    if (o.sync_managers) derive_sync_managers(device, intent, context);
    if (o.fmmus && device.fmmus.empty()) derive_fmmus(device);
    if (o.mapping_objects) derive_mapping_objects(device, intent, context);
    if (o.assignment_objects) derive_assignment_objects(device, context);
    if (o.sm_types_object) derive_sm_types_object(device, context);

    Dictionary* dictionary = dictionary_of(device, false);
    if (device.mailbox && device.mailbox->coe)
        derive_init_values(device.mailbox->coe->init_cmds, intent.init_values, dictionary, context);
    if (dictionary) {
        if (o.data_types) derive_data_types(*dictionary, context);
        sort_objects(*dictionary);
    }
}

void derive_module(Module& module, const ModuleIntent& intent, const Device* host, const std::string& path,
                   Diagnostics& diagnostics) {
    using namespace derive;
    Context context(path, diagnostics);
    Dictionary* dictionary = module.profile && module.profile->dictionary ? &*module.profile->dictionary : nullptr;
    const Dictionary* lookup = dictionary ? dictionary : (host ? host->dictionary() : nullptr);
    if (intent.options.pdo_entries) {
        derive_pdo_entries(module.rx_pdos, lookup, context);
        derive_pdo_entries(module.tx_pdos, lookup, context);
    }
    if (intent.options.pdo_assignment && host) {
        std::optional<std::uint32_t> outputs, inputs;
        for (std::uint32_t n = 0; n < host->sms.size(); ++n) {
            if (!outputs && host->sms[n].type == "Outputs") outputs = n;
            if (!inputs && host->sms[n].type == "Inputs") inputs = n;
        }
        auto assign = [&](std::vector<Pdo>& pdos, const std::vector<bool>& wanted, std::optional<std::uint32_t> sm) {
            for (std::size_t i = 0; i < pdos.size(); ++i)
                if (!pdos[i].sm && sm && (i >= wanted.size() || wanted[i])) pdos[i].sm = sm;
        };
        assign(module.rx_pdos, intent.rx_assign, outputs);
        assign(module.tx_pdos, intent.tx_assign, inputs);
    }
    if (module.mailbox && module.mailbox->coe)
        derive_init_values(module.mailbox->coe->init_cmds, intent.init_values, lookup, context);
    if (dictionary) {
        if (intent.options.data_types) derive_data_types(*dictionary, context);
        sort_objects(*dictionary);
    }
}

void derive_groups(EtherCATInfo& info, const std::vector<bool>& devices) {
    for (std::size_t i = 0; i < info.devices.size(); ++i) {
        const Device& device = info.devices[i];
        if (i < devices.size() && !devices[i]) continue;
        if (!device.group_type || device.group_type->empty() || info.find_group(*device.group_type)) continue;
        Group g;
        g.type = *device.group_type;
        g.type_pos = g.pos = device.group_type_pos;
        g.names.push_back(LocalizedText{g.type, std::nullopt, device.group_type_pos});
        info.groups.push_back(std::move(g));
    }
}

}  // namespace esi
