// The run-time dictionary from the model (coe_dictionary_build.hpp).

#include "sim/coe_dictionary_build.hpp"

#include <algorithm>
#include <map>

#include "esi/derive/derive.hpp"
#include "esi/ethercat/sync_manager_type.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/net/default_slave.hpp"

namespace esi::sim {

namespace {

// ESI Flags/Access with @ReadRestrictions/@WriteRestrictions (ETG.2000 AccessType): "ro", "rw",
// "wo", restricted to "PreOP", "SafeOP", "OP" or their combinations joined by '_'.
std::uint16_t state_bits(const std::optional<std::string>& restriction, std::uint16_t all) {
    if (!restriction || restriction->empty()) return all;
    const std::string& r = *restriction;
    const std::uint16_t lowest = all & static_cast<std::uint16_t>(-all);  // read_preop or write_preop
    std::uint16_t out = 0;
    if (r.find("PreOP") != std::string::npos) out |= lowest;
    if (r.find("SafeOP") != std::string::npos) out |= static_cast<std::uint16_t>(lowest << 1);
    // "OP" alone, or "_OP" after another state; "PreOP"/"SafeOP" contain "OP" too.
    if (r == "OP" || r.ends_with("_OP")) out |= static_cast<std::uint16_t>(lowest << 2);
    return out;
}

std::uint16_t access_of(const ObjectFlags* flags) {
    std::uint16_t out = 0;
    const std::string access = flags && flags->access ? *flags->access : "ro";
    if (access == "ro" || access == "rw")
        out |= state_bits(flags ? flags->access_read_restrictions : std::nullopt, access_bit::read_all);
    if (access == "rw" || access == "wo")
        out |= state_bits(flags ? flags->access_write_restrictions : std::nullopt, access_bit::write_all);
    if (flags && flags->pdo_mapping) {
        const std::string& m = *flags->pdo_mapping;
        if (m.find_first_of("Rr") != std::string::npos) out |= access_bit::rx_mappable;
        if (m.find_first_of("Tt") != std::string::npos) out |= access_bit::tx_mappable;
    }
    if (flags && flags->backup.value_or(0) != 0) out |= access_bit::backup;
    if (flags && flags->setting.value_or(0) != 0) out |= access_bit::setting;
    return out;
}

std::vector<std::uint8_t> number_bytes(const Number& number, std::size_t size) {
    std::vector<std::uint8_t> out(size, 0);
    const std::uint64_t bits = number.bits();
    for (std::size_t i = 0; i < size; ++i) out[i] = i < 8 ? static_cast<std::uint8_t>(bits >> (8 * i)) : (number.negative ? 0xFF : 0);
    return out;
}

// The default of an entry in CoE's byte order: DefaultData as written (ESI hexBinary is the
// transfer order), else DefaultValue, else DefaultString; zeros where the model gives none.
std::vector<std::uint8_t> default_bytes(const ObjectEntry& entry) {
    const std::size_t size = (entry.bit_size + 7u) / 8u;
    std::vector<std::uint8_t> out(size, 0);
    const bool is_string = entry.basic && (entry.basic->type_class == TypeClass::visible_string ||
                                           entry.basic->type_class == TypeClass::unicode_string);
    auto from = [&](const std::optional<HexData>& data, const std::optional<Number>& value,
                    const std::optional<std::string>& text) -> bool {
        if (data) {
            if (auto bytes = data->bytes()) {
                std::copy_n(bytes->begin(), std::min(bytes->size(), size), out.begin());
                return true;
            }
        }
        if (value && !is_string) {
            out = number_bytes(*value, size);
            return true;
        }
        if (text && is_string) {
            std::copy_n(text->begin(), std::min(text->size(), size), out.begin());
            return true;
        }
        return false;
    };
    if (entry.info && from(entry.info->default_data, entry.info->default_value, entry.info->default_string)) return out;
    if (entry.type_item) from(entry.type_item->default_data, entry.type_item->default_value, entry.type_item->default_string);
    return out;
}

CoeObject runtime_object(const DataTypeIndex& types, const Object& object) {
    const ObjectLayout layout = layout_of(types, object);
    CoeObject out;
    out.index = static_cast<std::uint16_t>(object.index);
    out.name = primary_text(object.names);
    out.code = layout.code == ObjectCode::var ? object_code::var
               : layout.code == ObjectCode::array ? object_code::array
                                                  : object_code::record;
    const ResolvedType type = resolve_type(types, object.type);
    if (type.basic) out.data_type = type.basic->coe_code;
    else if (type.definition && type.definition->index) out.data_type = static_cast<std::uint16_t>(*type.definition->index);
    for (const ObjectEntry& e : layout.entries) {
        if (e.subindex > 255) continue;
        CoeEntry entry;
        entry.subindex = static_cast<std::uint8_t>(e.subindex);
        entry.name = e.name.empty() ? out.name : e.name;
        entry.basic = e.basic;
        entry.data_type = e.basic ? e.basic->coe_code : 0;
        entry.bit_size = static_cast<std::uint32_t>(std::min<std::uint64_t>(e.bit_size, 0xFFFF * 8u));
        entry.bit_offset = static_cast<std::uint32_t>(std::min<std::uint64_t>(e.bit_offset, 0xFFFF * 8u));
        entry.access = access_of(e.flags);
        entry.default_value = default_bytes(e);
        entry.value = entry.default_value;
        out.entries.push_back(std::move(entry));
    }
    std::sort(out.entries.begin(), out.entries.end(), [](const CoeEntry& a, const CoeEntry& b) { return a.subindex < b.subindex; });
    return out;
}

// Objects for PDO entries no Dictionary declares: what a master can see of them is the entry's
// index, sub-index, size, type and name, and that it is mapped in that direction.
void add_objects_from_pdo_entries(const Device& device, CoeDictionary& dictionary) {
    struct Named {
        const PdoEntry* entry;
        PdoDirection direction;
    };
    std::map<std::uint32_t, std::map<std::uint32_t, Named>> missing;
    for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
        for (const Pdo& pdo : *list)
            for (const PdoEntry& e : pdo.entries)
                if (!e.is_padding() && !dictionary.find(e.index) && e.effective_subindex() <= 255 && e.bit_len > 0)
                    missing[e.index].emplace(e.effective_subindex(), Named{&e, pdo.direction});
    for (const auto& [index, entries] : missing) {
        if (index > 0xFFFF) continue;
        CoeObject o;
        o.index = static_cast<std::uint16_t>(index);
        o.from_model = false;
        const bool var = entries.size() == 1 && entries.begin()->first == 0;
        o.code = var ? object_code::var : object_code::record;
        o.name = primary_text(entries.begin()->second.entry->names);
        std::uint32_t offset = var ? 0 : 16;
        if (!var) {
            CoeEntry sub0;
            sub0.name = "SubIndex 000";
            sub0.basic = find_basic_type("USINT");
            sub0.data_type = sub0.basic ? sub0.basic->coe_code : 5;
            sub0.bit_size = 8;
            sub0.access = access_bit::read_all;
            sub0.default_value = {static_cast<std::uint8_t>(entries.rbegin()->first)};
            sub0.value = sub0.default_value;
            o.entries.push_back(std::move(sub0));
        }
        for (const auto& [subindex, named] : entries) {
            if (!var && subindex == 0) continue;
            CoeEntry e;
            e.subindex = static_cast<std::uint8_t>(subindex);
            e.name = primary_text(named.entry->names);
            e.basic = named.entry->data_type ? find_basic_type(*named.entry->data_type) : nullptr;
            e.data_type = e.basic ? e.basic->coe_code : 0;
            e.bit_size = named.entry->bit_len;
            if (e.bit_size >= 8 && offset % 8 != 0) offset += 8 - offset % 8;
            e.bit_offset = offset;
            offset += e.bit_size;
            e.access = named.direction == PdoDirection::rx
                           ? access_bit::read_all | access_bit::write_all | access_bit::rx_mappable
                           : access_bit::read_all | access_bit::tx_mappable;
            e.default_value.assign(e.byte_size(), 0);
            e.value = e.default_value;
            o.entries.push_back(std::move(e));
        }
        if (var) o.data_type = o.entries.front().data_type;
        dictionary.add(std::move(o));
    }
}

// A modular device runs with the modules esi-net places in its slots by default: their PDOs join the device's
// (indices moved by the slot increments, assigned to the SMs esi-net assigns them to), so the
// mapping objects derived below include them; the assignment objects get esi-net's default
// assignment (set_default_assignment).
struct DefaultModules {
    std::vector<net::ModuleObject> objects;
    std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> assignment;  // SM, PDO indices
};

DefaultModules add_default_modules(const EtherCATInfo& info, const Device& original, Device& device) {
    DefaultModules out;
    if (!original.slots || original.slots->slots.empty()) return out;
    // A device that is not one of the catalogue's comes configured (esi-sim's line builds it with
    // the modules NETWORK.yaml or esi-net placed); its PDOs and objects are taken as they are.
    const bool from_catalogue = std::any_of(info.devices.begin(), info.devices.end(), [&](const Device& d) { return &d == &original; });
    if (!from_catalogue) return out;
    Diagnostics ignored;  // what esi-net would report is lint's and esi-net's business
    net::DefaultSlave configured = net::configure_default_slave(info, original, ignored);
    if (configured.slave.modules.empty()) return out;
    for (const net::ConfiguredPdo& c : configured.slave.pdos) {
        // A device handed over with its modules already in place (esi-sim's line does that for
        // the modules esi-net places) has these PDOs.
        const std::vector<Pdo>& list = c.direction == PdoDirection::rx ? device.rx_pdos : device.tx_pdos;
        const bool present = std::any_of(list.begin(), list.end(), [&](const Pdo& p) { return p.index == c.index; });
        if (!c.module || present) continue;
        Pdo pdo;
        pdo.direction = c.direction;
        pdo.index = c.index;
        pdo.names.emplace_back().text = c.name;
        pdo.fixed = c.fixed;
        pdo.sm = c.sm;
        for (const net::ConfiguredEntry& e : c.entries) {
            PdoEntry entry;
            entry.index = e.index;
            entry.subindex = e.subindex;
            entry.bit_len = e.bit_len;
            entry.names.emplace_back().text = e.name;
            if (!e.data_type.empty()) entry.data_type = e.data_type;
            pdo.entries.push_back(std::move(entry));
        }
        (c.direction == PdoDirection::rx ? device.rx_pdos : device.tx_pdos).push_back(std::move(pdo));
    }
    for (const net::SmSetup& sm : configured.slave.sms) {
        if (!sm.is_process_data()) continue;
        std::vector<std::uint32_t> indices;
        for (std::size_t p : sm.pdos)
            if (std::find(indices.begin(), indices.end(), configured.slave.pdos[p].index) == indices.end())
                indices.push_back(configured.slave.pdos[p].index);
        out.assignment.emplace_back(sm.number, std::move(indices));
    }
    out.objects = std::move(configured.module_objects);
    return out;
}

// The assignment object of an SM set to `pdos`, as its value and its default; entries are added
// (UINT, after the last) where the object has fewer than the assignment needs.
void set_default_assignment(CoeDictionary& dictionary, std::uint32_t sm, const std::vector<std::uint32_t>& pdos) {
    CoeObject* object = dictionary.find(0x1C10 + sm);
    if (!object || object->entries.empty() || pdos.size() > 254) return;
    for (std::uint32_t k = 1; k <= pdos.size(); ++k) {
        if (object->entry(k)) continue;
        CoeEntry e = object->entries.size() > 1 ? object->entries.back() : CoeEntry{};
        e.subindex = static_cast<std::uint8_t>(k);
        e.basic = find_basic_type("UINT");
        e.data_type = 0x0006;
        e.bit_size = 16;
        e.bit_offset = object->entries.back().bit_offset + std::max<std::uint32_t>(object->entries.back().bit_size, 8);
        if (e.bit_offset < 16) e.bit_offset = 16;
        e.name = "SubIndex " + std::to_string(1000 + k).substr(1);
        if (e.access == 0) e.access = access_bit::read_all | access_bit::write_preop;
        e.value.assign(2, 0);
        e.default_value = e.value;
        object->entries.push_back(std::move(e));
    }
    for (CoeEntry& e : object->entries) {
        if (e.subindex == 0) e.set_unsigned(pdos.size());
        else e.set_unsigned(e.subindex <= pdos.size() ? pdos[e.subindex - 1u] : 0);
        e.default_value = e.value;
    }
}

// AL states in which a master sends an InitCmd of this transition (ETG.2000 InitCmd/Transition):
// the state the device is in when the command arrives.
std::uint16_t write_bits_for(const InitCmd& cmd) {
    std::uint16_t bits = 0;
    for (const Transition& t : cmd.transitions) {
        if (t.text == "IP" || t.text == "PS" || t.text == "PI") bits |= access_bit::write_preop;
        if (t.text == "SO" || t.text == "SP" || t.text == "SI") bits |= access_bit::write_safeop;
        if (t.text == "OS" || t.text == "OP" || t.text == "OI") bits |= access_bit::write_op;
    }
    return bits;
}

// The device's own CoE InitCmds are accepted: a master sends them because the ESI says so, and
// the firmware the ESI describes takes them. Where the Dictionary makes an InitCmd's target
// read-only, the entry becomes writable in the state the command arrives in; where it has no
// such object or entry, one is made of the command's size (an ESI that lists InitCmds for
// objects its Dictionary leaves out, e.g. a coupler's module configuration).
void accept_init_cmds(const Device& device, CoeDictionary& dictionary) {
    if (!device.mailbox || !device.mailbox->coe) return;
    for (const InitCmd& cmd : device.mailbox->coe->init_cmds) {
        const auto data = cmd.data.bytes();
        const std::uint16_t bits = write_bits_for(cmd);
        if (!cmd.index || *cmd.index > 0xFFFF || !data || data->empty() || data->size() > 0xFFFF || bits == 0) continue;
        const std::uint32_t subindex = cmd.subindex.value_or(0);
        if (subindex > 255) continue;
        CoeObject* object = dictionary.find(*cmd.index);
        if (cmd.complete_access.value_or(false)) {
            if (object)
                for (CoeEntry& e : object->entries) e.access |= bits;
            continue;
        }
        if (!object) {
            CoeObject o;
            o.index = static_cast<std::uint16_t>(*cmd.index);
            o.from_model = false;
            o.name = cmd.comment.value_or("");
            o.code = subindex == 0 ? object_code::var : object_code::record;
            if (subindex != 0) {
                CoeEntry sub0;
                sub0.name = "SubIndex 000";
                sub0.basic = find_basic_type("USINT");
                sub0.data_type = 0x0005;
                sub0.bit_size = 8;
                sub0.access = access_bit::read_all;
                sub0.default_value = {static_cast<std::uint8_t>(subindex)};
                sub0.value = sub0.default_value;
                o.entries.push_back(std::move(sub0));
            }
            object = &dictionary.add(std::move(o));
        }
        if (!object->entry(subindex)) {
            CoeEntry e;
            e.subindex = static_cast<std::uint8_t>(subindex);
            e.name = cmd.comment.value_or("");
            e.basic = find_basic_type("OCTET_STRING");
            e.data_type = e.basic ? e.basic->coe_code : 0x000A;
            e.bit_size = static_cast<std::uint32_t>(data->size() * 8);
            e.bit_offset = object->entries.empty() ? 0 : object->entries.back().bit_offset + object->entries.back().bit_size;
            e.access = access_bit::read_all;
            e.default_value.assign(data->size(), 0);
            e.value = e.default_value;
            auto at = std::lower_bound(object->entries.begin(), object->entries.end(), e.subindex,
                                       [](const CoeEntry& x, std::uint8_t si) { return x.subindex < si; });
            object->entries.insert(at, std::move(e));
        }
        object->entry(subindex)->access |= bits;
    }
}

}  // namespace

void fill_sm_types(CoeDictionary& dictionary, const std::vector<SmRole>& roles) {
    CoeObject* object = dictionary.find(0x1C00);
    if (!object || object->code == object_code::var) return;
    const bool any_value = std::any_of(object->entries.begin(), object->entries.end(),
                                       [](const CoeEntry& e) { return e.unsigned_value() != 0; });
    if (any_value) return;
    std::uint8_t count = 0;
    for (CoeEntry& e : object->entries) {
        if (e.subindex == 0 || e.subindex > roles.size()) continue;
        e.set_unsigned(static_cast<std::uint8_t>(roles[e.subindex - 1u]));  // SmRole's values are the codes
        e.default_value = e.value;
        count = std::max(count, e.subindex);
    }
    if (CoeEntry* sub0 = object->entry(0)) {
        sub0->set_unsigned(count);
        sub0->default_value = sub0->value;
    }
}

void add_missing_assignment_objects(CoeDictionary& dictionary) {
    const CoeObject* types = dictionary.find(0x1C00);
    if (!types) return;
    std::vector<std::uint16_t> missing;
    for (const CoeEntry& e : types->entries) {
        if (e.subindex == 0 || e.subindex > 32) continue;
        const auto type = ethercat::sync_manager_type_from_code(static_cast<std::uint8_t>(e.unsigned_value()));
        if (type != ethercat::SyncManagerType::outputs && type != ethercat::SyncManagerType::inputs) continue;
        const auto index = static_cast<std::uint16_t>(0x1C10 + e.subindex - 1u);
        if (!dictionary.find(index)) missing.push_back(index);
    }
    for (const std::uint16_t index : missing) {
        CoeObject o;
        o.index = index;
        o.code = object_code::array;
        o.data_type = 0x0006;  // UINT: the PDO indices an assignment holds
        o.name = "Sync manager " + std::to_string(index - 0x1C10) + " PDO assignment";
        o.from_model = false;
        CoeEntry count;
        count.subindex = 0;
        count.name = "Number of assigned PDOs";
        count.basic = find_basic_type("USINT");
        count.data_type = 0x0005;
        count.bit_size = 8;
        count.access = access_bit::read_all | access_bit::write_preop;
        count.value.assign(1, 0);
        count.default_value = count.value;
        o.entries.push_back(std::move(count));
        dictionary.add(std::move(o));
    }
}

DeviceModel build_device_model(const EtherCATInfo& info, const Device& device, Diagnostics& diagnostics) {
    DeviceModel model;
    model.device = device;
    model.vendor_id = info.vendor ? info.vendor->id.value_or(0) : 0;
    Device& d = model.device;
    model.dictionary_from_model = d.dictionary() != nullptr;
    // The objects that follow from the rest of the device, added only where the model has none
    // (derivation never replaces what a source declares). A device without CoE gets them too:
    // the stack lays out its process image from 0x1C1x and 0x16xx/0x1Axx like any other.
    if (!d.dictionary()) {
        if (d.profiles.empty()) d.profiles.emplace_back();
        d.profiles.front().dictionary.emplace();
    }
    const DefaultModules modules = add_default_modules(info, device, d);
    DeviceIntent intent;
    intent.options = DeriveOptions::none();
    intent.options.identity_object = intent.options.device_type_object = true;
    intent.options.mapping_objects = intent.options.assignment_objects = intent.options.sm_types_object = true;
    intent.vendor_id = model.vendor_id;
    Diagnostics derived;
    derive_device(d, intent, {}, derived);
    // Derivation reports contradictions of the source (lint's business); the stack answers what
    // the objects it could build say, so its findings are not errors here.
    (void)derived;
    (void)diagnostics;

    if (const Dictionary* dictionary = d.dictionary()) {
        const DataTypeIndex types(dictionary);
        for (const Object& object : dictionary->objects) {
            if (object.index > 0xFFFF) continue;
            CoeObject o = runtime_object(types, object);
            o.from_model = model.dictionary_from_model && device.dictionary() && device.dictionary()->find_object(object.index);
            model.dictionary.add(std::move(o));
        }
    }
    for (const net::ModuleObject& m : modules.objects) {
        if (m.index > 0xFFFF) continue;
        CoeObject o = runtime_object(DataTypeIndex(m.dictionary), *m.object);
        o.index = static_cast<std::uint16_t>(m.index);
        model.dictionary.add(std::move(o));
    }
    for (const auto& [sm, pdos] : modules.assignment) set_default_assignment(model.dictionary, sm, pdos);
    add_objects_from_pdo_entries(d, model.dictionary);
    accept_init_cmds(d, model.dictionary);
    add_missing_assignment_objects(model.dictionary);
    return model;
}

}  // namespace esi::sim
