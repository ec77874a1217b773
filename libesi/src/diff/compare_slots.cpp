// Slots of a modular device (ETG.2001): the n-th Slot is slot n, so slots pair up by position;
// the modules a slot accepts are sets (ModuleIdent values, ModuleClass names).

#include <map>

#include <fmt/format.h>

#include "diff/compare.hpp"

namespace esi::diff_detail {

namespace {

// A bound that may only grow (max) or shrink (min) without breaking configurations.
void bound(Recorder& r, const std::string& path, std::string_view name, const std::optional<std::uint32_t>& a,
           const std::optional<std::uint32_t>& b, bool is_max, SourcePos pa, SourcePos pb) {
    if (a == b) return;
    bool narrowed = false;
    if (is_max)
        narrowed = b && (!a || *b < *a);  // absent = unbounded
    else
        narrowed = b.value_or(0) > a.value_or(0);
    r.value(narrowed ? ChangeKind::slot_instances_narrowed : ChangeKind::slot_instances_widened, attr(path, name), name, dec(a),
            dec(b), pa, pb);
}

std::string class_key(const SlotModuleClass& c) {
    return c.vendor_id ? fmt::format("{} vendor {}", c.class_name, hex(*c.vendor_id, 8)) : c.class_name;
}

void compare_slot(Recorder& r, const std::string& p, const Slot& a, const Slot& b) {
    compare_texts(r, ChangeKind::name_changed, p, "Name", a.names, b.names, a.pos, b.pos);
    bound(r, p, "MinInstances", a.min_instances, b.min_instances, false, a.pos, b.pos);
    bound(r, p, "MaxInstances", a.max_instances, b.max_instances, true, a.pos, b.pos);
    const auto layout = [&](std::string_view name, const std::optional<std::uint32_t>& x, const std::optional<std::uint32_t>& y,
                            bool as_hex) {
        r.value(ChangeKind::slot_layout_changed, attr(p, name), name, as_hex ? hex(x) : dec(x), as_hex ? hex(y) : dec(y), a.pos,
                b.pos);
    };
    layout("SlotGroup", a.slot_group, b.slot_group, false);
    layout("SlotPdoIncrement", a.slot_pdo_increment, b.slot_pdo_increment, true);
    layout("SlotGroupPdoIncrement", a.slot_group_pdo_increment, b.slot_group_pdo_increment, true);
    layout("SlotIndexIncrement", a.slot_index_increment, b.slot_index_increment, true);
    layout("SlotGroupIndexIncrement", a.slot_group_index_increment, b.slot_group_index_increment, true);
    r.value(ChangeKind::slot_default_changed, attr(p, "Default"), "Default", hex(a.default_ident, 8), hex(b.default_ident, 8),
            a.pos, b.pos);
    r.value(ChangeKind::slot_default_changed, attr(p, "Fallback"), "Fallback", hex(a.fallback, 8), hex(b.fallback, 8), a.pos,
            b.pos);

    std::map<std::uint32_t, const SlotModuleIdent*> ia;
    std::map<std::uint32_t, const SlotModuleIdent*> ib;
    for (const auto& m : a.module_idents) ia.emplace(m.value, &m);
    for (const auto& m : b.module_idents) ib.emplace(m.value, &m);
    for (const auto& [value, m] : ib) {
        const std::string mp = child(p, indexed("ModuleIdent", hex(value, 8)));
        const auto it = ia.find(value);
        if (it == ia.end()) {
            r.add(ChangeKind::slot_module_added, mp, std::nullopt, hex(value, 8), a.pos, m->pos,
                  fmt::format("slot accepts module {}", hex(value, 8)));
            continue;
        }
        r.value(ChangeKind::slot_default_changed, attr(mp, "Default"), "ModuleIdent@Default", hex(it->second->default_ident, 8),
                hex(m->default_ident, 8), it->second->pos, m->pos);
    }
    for (const auto& [value, m] : ia)
        if (!ib.count(value))
            r.add(ChangeKind::slot_module_removed, child(p, indexed("ModuleIdent", hex(value, 8))), hex(value, 8), std::nullopt,
                  m->pos, b.pos, fmt::format("slot no longer accepts module {}", hex(value, 8)));

    std::map<std::string, const SlotModuleClass*> ca;
    std::map<std::string, const SlotModuleClass*> cb;
    for (const auto& c : a.module_classes) ca.emplace(class_key(c), &c);
    for (const auto& c : b.module_classes) cb.emplace(class_key(c), &c);
    for (const auto& [key, c] : cb) {
        const std::string cp = child(p, indexed("ModuleClass", key));
        const auto it = ca.find(key);
        if (it == ca.end()) {
            r.add(ChangeKind::slot_module_added, cp, std::nullopt, key, a.pos, c->pos,
                  fmt::format("slot accepts module class {}", key));
            continue;
        }
        compare_texts(r, ChangeKind::name_changed, cp, "Name", it->second->names, c->names, it->second->pos, c->pos);
        compare_extras(r, cp, it->second->extras, c->extras, it->second->pos, c->pos);
    }
    for (const auto& [key, c] : ca)
        if (!cb.count(key))
            r.add(ChangeKind::slot_module_removed, child(p, indexed("ModuleClass", key)), key, std::nullopt, c->pos, b.pos,
                  fmt::format("slot no longer accepts module class {}", key));

    compare_images(r, p, a.images, b.images, a.pos, b.pos);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

}  // namespace

void compare_slots(Recorder& r, const std::string& path, const std::optional<Slots>& a, const std::optional<Slots>& b,
                   SourcePos old_parent, SourcePos new_parent) {
    if (!a && !b) return;
    static const Slots none;
    const Slots& x = a ? *a : none;
    const Slots& y = b ? *b : none;
    const SourcePos px = a ? a->pos : old_parent;
    const SourcePos py = b ? b->pos : new_parent;
    bound(r, path, "MaxSlotCount", x.max_slot_count, y.max_slot_count, true, px, py);
    bound(r, path, "MaxSlotGroupCount", x.max_slot_group_count, y.max_slot_group_count, true, px, py);
    const auto layout = [&](std::string_view name, const std::optional<std::uint32_t>& p, const std::optional<std::uint32_t>& q) {
        r.value(ChangeKind::slot_layout_changed, attr(path, name), name, hex(p), hex(q), px, py);
    };
    layout("SlotPdoIncrement", x.slot_pdo_increment, y.slot_pdo_increment);
    layout("SlotGroupPdoIncrement", x.slot_group_pdo_increment, y.slot_group_pdo_increment);
    layout("SlotIndexIncrement", x.slot_index_increment, y.slot_index_increment);
    layout("SlotGroupIndexIncrement", x.slot_group_index_increment, y.slot_group_index_increment);

    const std::size_t n = std::max(x.slots.size(), y.slots.size());
    for (std::size_t i = 0; i < n; ++i) {
        const std::string p = child(path, indexed("Slot", std::to_string(i + 1)));
        if (i >= x.slots.size()) {
            const Slot& s = y.slots[i];
            r.add(ChangeKind::slot_added, p, std::nullopt, primary_text(s.names), px, s.pos,
                  fmt::format("slot {} {} added", i + 1, quote(primary_text(s.names))));
        } else if (i >= y.slots.size()) {
            const Slot& s = x.slots[i];
            r.add(ChangeKind::slot_removed, p, primary_text(s.names), std::nullopt, s.pos, py,
                  fmt::format("slot {} {} removed", i + 1, quote(primary_text(s.names))));
        } else {
            compare_slot(r, p, x.slots[i], y.slots[i]);
        }
    }
    compare_extras(r, path, x.extras, y.extras, px, py);
}

}  // namespace esi::diff_detail
