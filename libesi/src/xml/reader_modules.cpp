// ESI XML -> model: Module (ModuleType of EtherCATBase.xsd, in Descriptions/Modules or an
// EtherCATModule root) and the Slots of a modular device.

#include "xml/reader_context.hpp"

namespace esi::xml_reader {

void Reader::read_module(Module& m, const Element n) {
    m.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(m.extras, a);
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Type")) {
            text(m.type, c);
            m.type_pos = pos_of(c);
            for (const Attr& a : c.attributes()) {
                const std::string_view an = a.name;
                if (is(an, "ModuleIdent")) m.module_ident = u32(a, c).value_or(0);
                else if (is(an, "ModuleClass")) m.module_class = a.value;
                else if (is(an, "ModulePdoGroup")) m.module_pdo_group = i32(a, c);
                else keep(m.type_extras, a);
            }
        } else if (is(name, "Name")) localized(m.names, c);
        else if (is(name, "RxPdo")) read_pdo(m.rx_pdos.emplace_back(), c, PdoDirection::rx);
        else if (is(name, "TxPdo")) read_pdo(m.tx_pdos.emplace_back(), c, PdoDirection::tx);
        else if (is(name, "Mailbox")) read_mailbox(m.mailbox.emplace(), c);
        else if (is(name, "Profile")) read_profile(m.profile.emplace(), c);
        else if (is(name, "DcOpModeName")) text(m.dc_op_mode_name, c);
        else if (!read_image(m.images, c, name)) keep(m.extras, c, previous);
    });
}

void Reader::read_slot(Slot& s, const Element n) {
    s.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "SlotGroup")) s.slot_group = u32(a, n);
        else if (is(an, "MinInstances")) s.min_instances = u32(a, n).value_or(0);
        else if (is(an, "MaxInstances")) s.max_instances = u32(a, n).value_or(0);
        else if (is(an, "SlotPdoIncrement")) s.slot_pdo_increment = u32(a, n);
        else if (is(an, "SlotGroupPdoIncrement")) s.slot_group_pdo_increment = u32(a, n);
        else if (is(an, "SlotIndexIncrement")) s.slot_index_increment = u32(a, n);
        else if (is(an, "SlotGroupIndexIncrement")) s.slot_group_index_increment = u32(a, n);
        else if (is(an, "Default")) s.default_ident = u32(a, n);
        else if (is(an, "Fallback")) s.fallback = u32(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Name")) localized(s.names, c);
        else if (is(name, "ModuleIdent")) {
            SlotModuleIdent id;
            id.pos = pos_of(c);
            id.value = u32(c).value_or(0);
            for (const Attr& a : c.attributes())
                if (is(a.name, "Default")) id.default_ident = u32(a, c);
            s.module_idents.push_back(id);
        } else if (is(name, "ModuleClass")) {
            SlotModuleClass mc;
            mc.pos = pos_of(c);
            for (const Attr& a : c.attributes()) keep(mc.extras, a);
            for_children(c, [&](const Element cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "Class")) text(mc.class_name, cc);
                else if (is(cn, "VendorId")) mc.vendor_id = u32(cc);
                else if (is(cn, "Name")) localized(mc.names, cc);
                else keep(mc.extras, cc, prev);
            });
            s.module_classes.push_back(std::move(mc));
        } else if (!read_image(s.images, c, name)) keep(s.extras, c, previous);
    });
}

void Reader::read_slots(Slots& s, const Element n) {
    s.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "MaxSlotCount")) s.max_slot_count = u32(a, n);
        else if (is(an, "MaxSlotGroupCount")) s.max_slot_group_count = u32(a, n);
        else if (is(an, "SlotPdoIncrement")) s.slot_pdo_increment = u32(a, n);
        else if (is(an, "SlotGroupPdoIncrement")) s.slot_group_pdo_increment = u32(a, n);
        else if (is(an, "SlotIndexIncrement")) s.slot_index_increment = u32(a, n);
        else if (is(an, "SlotGroupIndexIncrement")) s.slot_group_index_increment = u32(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Slot")) read_slot(s.slots.emplace_back(), c);
        else keep(s.extras, c, previous);
    });
}

}  // namespace esi::xml_reader
