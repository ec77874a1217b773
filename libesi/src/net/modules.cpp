// Modules in slots (ETG.2000 Slots, ETG.2001 modular devices): which module each slot of a
// modular device holds, from NETWORK.yaml or the ESI's defaults, and the PDOs they bring.

#include <fmt/format.h>

#include "esi/yaml/reader.hpp"
#include "slave_context.hpp"

namespace esi::net {

namespace {

// One slot position: a Slot element repeats up to MaxInstances times.
struct SlotPosition {
    const Slot* slot = nullptr;
    std::uint32_t instance = 0;
};

std::vector<SlotPosition> slot_positions(const Slots& slots) {
    std::vector<SlotPosition> out;
    for (const Slot& s : slots.slots) {
        const std::uint32_t count = std::max<std::uint32_t>(1, s.max_instances);
        for (std::uint32_t i = 0; i < count && out.size() < 4096; ++i) out.push_back({&s, i});
    }
    return out;
}

std::string slot_label(const SlotPosition& p, std::uint32_t number) {
    const std::string& name = primary_text(p.slot->names);
    return name.empty() ? fmt::format("slot {}", number) : fmt::format("slot {} ({})", number, name);
}

const Module* find_module_by_ident(const EtherCATInfo& info, std::uint32_t ident) {
    for (const Module& m : info.modules)
        if (m.module_ident == ident) return &m;
    return nullptr;
}

bool slot_accepts(const Slot& slot, const Module& module) {
    for (const SlotModuleIdent& id : slot.module_idents)
        if (id.value == module.module_ident) return true;
    for (const SlotModuleClass& c : slot.module_classes)
        if (module.module_class && *module.module_class == c.class_name) return true;
    return false;
}

// The modules a slot takes, for messages.
std::string accepted_list(const EtherCATInfo& info, const Slot& slot) {
    std::string out;
    for (const Module& m : info.modules) {
        if (!slot_accepts(slot, m)) continue;
        out += (out.empty() ? "" : ", ") + fmt::format("'{}' ({})", m.type, hex_index(m.module_ident));
    }
    return out.empty() ? "none in this ESI file" : out;
}

const Module* default_module(const EtherCATInfo& info, const Slot& slot) {
    if (slot.default_ident)
        if (const Module* m = find_module_by_ident(info, *slot.default_ident)) return m;
    for (const SlotModuleIdent& id : slot.module_idents)
        if (id.default_ident.value_or(0) != 0)
            if (const Module* m = find_module_by_ident(info, id.value)) return m;
    return nullptr;
}

}  // namespace

std::string hex_index(std::uint32_t value) { return fmt::format("0x{:04X}", value); }

void configure_modules(SlaveContext& c) {
    const bool has_slots = c.device.slots && !c.device.slots->slots.empty();
    if (!has_slots) {
        if (c.spec.modules && !c.spec.modules->empty())
            c.error(c.spec.modules_pos, "net-module", c.device.type.text + " has no slots; it takes no modules");
        return;
    }
    const std::vector<SlotPosition> positions = slot_positions(*c.device.slots);
    std::vector<const Module*> chosen(positions.size(), nullptr);
    std::vector<bool> given(positions.size(), false);
    std::vector<bool> refused(positions.size(), false);  // reported already
    if (c.spec.modules) {
        std::size_t next = 0;
        for (const ModuleSpec& m : *c.spec.modules) {
            std::size_t at = next;
            if (m.slot) {
                at = *m.slot;
            } else if (m.slot_name) {
                at = positions.size();
                for (std::size_t i = 0; i < positions.size(); ++i)
                    if (primary_text(positions[i].slot->names) == *m.slot_name && !given[i]) {
                        at = i;
                        break;
                    }
                if (at == positions.size()) {
                    std::vector<std::string_view> names;
                    for (const SlotPosition& p : positions) names.push_back(primary_text(p.slot->names));
                    c.error(m.pos, "net-module", "no free slot named '" + *m.slot_name + "'" + yaml::did_you_mean(*m.slot_name, names));
                    continue;
                }
            }
            next = at + 1;
            if (at >= positions.size()) {
                c.error(m.pos, "net-module",
                        fmt::format("{} has {} slot positions; there is no slot {}", c.device.type.text, positions.size(), at));
                continue;
            }
            if (given[at]) {
                // Two entries for one slot: taking either would drop the other without a word.
                c.error(m.pos, "net-module",
                        fmt::format("{} is given twice; each slot holds one module (or null for empty)",
                                    slot_label(positions[at], static_cast<std::uint32_t>(at))));
                continue;
            }
            given[at] = true;
            if (m.empty) continue;
            const Slot& slot = *positions[at].slot;
            const Module* module = nullptr;
            if (m.ident) {
                module = find_module_by_ident(c.info, *m.ident);
            } else if (m.type) {
                for (const Module& candidate : c.info.modules)
                    if (candidate.type == *m.type) module = &candidate;
            }
            if (!module || !slot_accepts(slot, *module)) {
                refused[at] = true;
                const std::string what = m.ident ? hex_index(*m.ident) : "'" + m.type.value_or("") + "'";
                c.error(m.pos, "net-module",
                        fmt::format("{} {} take module {}; it takes: {}", slot_label(positions[at], static_cast<std::uint32_t>(at)),
                                    module ? "does not" : "cannot", what, accepted_list(c.info, slot)));
                continue;
            }
            chosen[at] = module;
        }
    }
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (!given[i] && !chosen[i] && positions[i].instance < positions[i].slot->min_instances)
            chosen[i] = default_module(c.info, *positions[i].slot);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const SlotPosition& p = positions[i];
        if (!chosen[i]) {
            if (p.instance < p.slot->min_instances && !refused[i])
                c.error(c.spec.modules ? c.spec.modules_pos : c.spec.pos, "net-module",
                        fmt::format("{} needs a module (MinInstances {}); it takes: {}", slot_label(p, static_cast<std::uint32_t>(i)),
                                    p.slot->min_instances, accepted_list(c.info, *p.slot)));
            continue;
        }
        c.slave.modules.push_back({static_cast<std::uint32_t>(i), primary_text(p.slot->names), chosen[i]});
    }
}

std::uint32_t slot_index(const SlaveContext& c, std::size_t module, std::uint32_t index, bool depend_on_slot) {
    if (!depend_on_slot || !c.device.slots) return index;
    const ModuleInSlot& m = c.slave.modules[module];
    const Slots& slots = *c.device.slots;
    std::uint32_t increment = slots.slot_index_increment.value_or(0);
    std::uint32_t number = 0;
    for (const Slot& s : slots.slots) {
        const std::uint32_t count = std::max<std::uint32_t>(1, s.max_instances);
        if (m.slot < number + count) {
            increment = s.slot_index_increment.value_or(increment);
            break;
        }
        number += count;
    }
    return index + m.slot * increment;
}

FoundObject find_object(const SlaveContext& c, std::uint32_t index) {
    if (const Dictionary* d = c.device.dictionary())
        if (const Object* o = d->find_object(index)) return {d, o};
    for (std::size_t i = 0; i < c.slave.modules.size(); ++i) {
        const Module& m = *c.slave.modules[i].module;
        if (!m.profile || !m.profile->dictionary) continue;
        for (const Object& o : m.profile->dictionary->objects)
            if (slot_index(c, i, o.index, o.index_depend_on_slot.value_or(false)) == index) return {&*m.profile->dictionary, &o};
    }
    return {};
}

bool has_dictionary(const SlaveContext& c) {
    if (c.device.dictionary()) return true;
    for (const ModuleInSlot& m : c.slave.modules)
        if (m.module->profile && m.module->profile->dictionary) return true;
    return false;
}

std::vector<AvailablePdo> available_pdos(const SlaveContext& c) {
    std::vector<AvailablePdo> out;
    for (const auto* list : {&c.device.rx_pdos, &c.device.tx_pdos})
        for (const Pdo& p : *list) out.push_back({&p, p.index, std::nullopt, 0});
    for (std::size_t i = 0; i < c.slave.modules.size(); ++i) {
        const ModuleInSlot& m = c.slave.modules[i];
        std::uint32_t increment = c.device.slots->slot_pdo_increment.value_or(0);
        std::uint32_t number = 0;
        for (const Slot& s : c.device.slots->slots) {
            const std::uint32_t count = std::max<std::uint32_t>(1, s.max_instances);
            if (m.slot < number + count) {
                increment = s.slot_pdo_increment.value_or(increment);
                break;
            }
            number += count;
        }
        for (const auto* list : {&m.module->rx_pdos, &m.module->tx_pdos})
            for (const Pdo& p : *list) {
                const std::uint32_t index = p.index_depend_on_slot.value_or(false) ? p.index + m.slot * increment : p.index;
                out.push_back({&p, index, i, m.slot});
            }
    }
    return out;
}

}  // namespace esi::net
