// Slots and modules of a modular device (ETG.2001): each slot with the instances it allows and the
// modules it accepts, then each accepted module with its PDOs (tables and pictures).

#include <string>

#include "doc/markup.hpp"
#include "doc/modules.hpp"
#include "doc/sections.hpp"

namespace esi::doc {

namespace {

std::string module_label(const Module& m, const PageContext& context) {
    const std::string& name = context.text(m.names);
    return m.type + (name.empty() || name == m.type ? "" : " (" + name + ")");
}

ViewValue modules_list(const EtherCATInfo& info, const std::vector<std::size_t>& positions, const PageContext& context) {
    ViewArena& arena = *context.arena;
    ListBuilder modules(arena);
    for (const std::size_t m : positions) {
        const Module& module = info.modules[m];
        const std::string owner = "m" + std::to_string(m);
        PageObject o(arena);
        o.add("id", owner);
        o.add("type", module.type);
        o.add("name", context.text(module.names));
        o.add("ident_hex", hex(module.module_ident, 8));
        o.add("class", module.module_class.value_or(""));
        o.add("pdos", pdos_list(module.rx_pdos, module.tx_pdos, owner, context));
        modules.add(o.finish());
    }
    return modules.finish();
}

}  // namespace

ViewValue modules_section(const Device& device, const PageContext& context) {
    if (!device.slots || !context.info) return ViewValue::null();
    const EtherCATInfo& info = *context.info;
    ViewArena& arena = *context.arena;

    ListBuilder slots(arena);
    for (std::size_t s = 0; s < device.slots->slots.size(); ++s) {
        const Slot& slot = device.slots->slots[s];
        std::string accepts;
        for (const auto& ident : slot.module_idents) accepts += (accepts.empty() ? "" : ", ") + hex(ident.value, 8);
        for (const auto& c : slot.module_classes) accepts += (accepts.empty() ? "" : ", ") + std::string("class ") + c.class_name;
        std::string modules;
        for (const Module& m : info.modules)
            if (slot_accepts(slot, m)) modules += (modules.empty() ? "" : ", ") + module_label(m, context);
        const std::uint32_t min = slot.min_instances, max = slot.max_instances;
        PageObject o(arena);
        o.add("number", s);
        o.add("name", context.text(slot.names));
        o.add("instances", min == max ? std::to_string(min) : std::to_string(min) + "–" + std::to_string(max));
        o.add("accepts", accepts);
        o.add("modules", modules);
        o.add("default_hex", slot.default_ident ? hex(*slot.default_ident, 8) : std::string());
        slots.add(o.finish());
    }

    PageObject section(arena);
    section.add("slot_count", device.slots->slots.size());
    section.add("has_slots", !device.slots->slots.empty());
    section.add("slots", slots.finish());
    section.add("modules", modules_list(info, accepted_modules(info, device), context));
    return section.finish();
}

ViewValue all_modules_section(const EtherCATInfo& info, const PageContext& context) {
    if (info.modules.empty()) return ViewValue::null();
    std::vector<std::size_t> all(info.modules.size());
    for (std::size_t m = 0; m < all.size(); ++m) all[m] = m;
    PageObject section(*context.arena);
    section.add("slot_count", 0);
    section.add("has_slots", false);
    section.add("slots", ListBuilder(*context.arena).finish());
    section.add("modules", modules_list(info, all, context));
    return section.finish();
}

}  // namespace esi::doc
