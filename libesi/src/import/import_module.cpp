// `modules:` (pluggable units, ETG.2001 Modular Device Profile) and a device's `slots:`.

#include "import/import_writer.hpp"

namespace esi::import_detail {

YNode ImportWriter::slots(const Slots& s, const std::string& path) {
    YNode m = YNode::map();
    YNode list = YNode::seq();
    for (std::size_t i = 0; i < s.slots.size(); ++i) {
        const Slot& slot = s.slots[i];
        const std::string sp = path + "/Slots/Slot[" + std::to_string(i + 1) + "]";
        YNode x = YNode::map();
        names(x, "name", slot.names, sp);
        if (slot.module_idents.empty() == slot.module_classes.empty())
            warn(sp, "a slot with both (or neither) ModuleIdent and ModuleClass cannot be written exactly");
        if (!slot.module_idents.empty()) {
            YNode ms = YNode::seq();
            for (const auto& id : slot.module_idents) {
                if (!id.default_ident) {
                    ms.push(YNode::hex(id.value, 8));
                    continue;
                }
                YNode mm = YNode::map();
                mm.set("module", YNode::hex(id.value, 8));
                mm.set("default", YNode::hex(*id.default_ident, 8));
                ms.push(std::move(mm));
            }
            x.set("modules", std::move(ms));
        }
        if (!slot.module_classes.empty()) {
            YNode cs = YNode::seq();
            for (const auto& c : slot.module_classes) {
                YNode cm = YNode::map();
                cm.set("class", YNode::text(c.class_name));
                if (c.vendor_id) cm.set("vendor_id", YNode::hex(*c.vendor_id, 8));
                names(cm, "name", c.names, sp);
                set_extras(cm, "xml", c.extras);
                cs.push(std::move(cm));
            }
            x.set("module_classes", std::move(cs));
        }
        if (slot.default_ident) x.set("default", YNode::hex(*slot.default_ident, 8));
        if (slot.fallback) x.set("fallback", YNode::hex(*slot.fallback, 8));
        if (slot.slot_group) x.set("slot_group", YNode::unsigned_integer(*slot.slot_group));
        x.set("min_instances", YNode::unsigned_integer(slot.min_instances));
        x.set("max_instances", YNode::unsigned_integer(slot.max_instances));
        if (slot.slot_pdo_increment) x.set("slot_pdo_increment", YNode::unsigned_integer(*slot.slot_pdo_increment));
        if (slot.slot_group_pdo_increment) x.set("slot_group_pdo_increment", YNode::unsigned_integer(*slot.slot_group_pdo_increment));
        if (slot.slot_index_increment) x.set("slot_index_increment", YNode::hex(*slot.slot_index_increment, 4));
        if (slot.slot_group_index_increment) x.set("slot_group_index_increment", YNode::hex(*slot.slot_group_index_increment, 4));
        images(x, slot.images);
        set_extras(x, "xml", slot.extras);
        list.push(std::move(x));
    }
    m.set("list", std::move(list));
    if (s.max_slot_count) m.set("max_slot_count", YNode::unsigned_integer(*s.max_slot_count));
    if (s.max_slot_group_count) m.set("max_slot_group_count", YNode::unsigned_integer(*s.max_slot_group_count));
    if (s.slot_pdo_increment) m.set("slot_pdo_increment", YNode::unsigned_integer(*s.slot_pdo_increment));
    if (s.slot_group_pdo_increment) m.set("slot_group_pdo_increment", YNode::unsigned_integer(*s.slot_group_pdo_increment));
    if (s.slot_index_increment) m.set("slot_index_increment", YNode::hex(*s.slot_index_increment, 4));
    if (s.slot_group_index_increment) m.set("slot_group_index_increment", YNode::hex(*s.slot_group_index_increment, 4));
    set_extras(m, "xml", s.extras);
    return m;
}

YNode ImportWriter::module(const Module& mo) {
    const std::string path = "Modules/Module[" + hex_text(mo.module_ident, 8) + "]";
    YNode m = YNode::map();
    m.set("type", YNode::text(mo.type));
    m.set("ident", YNode::hex(mo.module_ident, 8));
    if (mo.module_class) m.set("class", YNode::text(*mo.module_class));
    if (mo.module_pdo_group) m.set("pdo_group", YNode::integer(*mo.module_pdo_group));
    set_extras(m, "type_xml", mo.type_extras);
    names(m, "name", mo.names, path, true);
    images(m, mo.images);
    const OmitPlan none;
    if (mo.profile) {
        m.set("profile", profile(*mo.profile));
        if (mo.profile->dictionary) dictionary(m, *mo.profile->dictionary, path, none, nullptr);
    }
    if (mo.mailbox) {
        m.set("mailbox", mailbox(*mo.mailbox, nullptr, none, path + "/Mailbox"));
        if (mo.mailbox->coe && !mo.mailbox->coe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mo.mailbox->coe->init_cmds.size(); ++i)
                list.push(init_cmd(mo.mailbox->coe->init_cmds[i], MailboxProtocol::coe, path + "/Mailbox/CoE/InitCmd[" + std::to_string(i + 1) + "]"));
            m.set("init", std::move(list));
        }
    }
    for (const auto* pdos : {&mo.rx_pdos, &mo.tx_pdos}) {
        if (pdos->empty()) continue;
        YNode list = YNode::seq();
        for (const auto& p : *pdos) list.push(pdo(p, none, path));
        m.set(pdos == &mo.rx_pdos ? "rxpdo" : "txpdo", std::move(list));
    }
    if (mo.dc_op_mode_name) m.set("dc_op_mode", YNode::text(*mo.dc_op_mode_name));
    m.set("derive", YNode::boolean(false));
    set_extras(m, "xml", mo.extras);
    return m;
}

}  // namespace esi::import_detail
