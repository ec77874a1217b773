// `modules:` (pluggable units, ETG.2001 Modular Device Profile) and a device's `slots:`.
// Slots name the modules they take by Type text or by ModuleIdent.

#include <algorithm>

#include "esi/text_distance.hpp"
#include "yaml/source_parser.hpp"

namespace esi::yaml {

std::optional<ParsedModule> SourceParser::module(const Node& node) {
    const auto f = r_.mapping(node, Context::module, "a module");
    if (!f) return std::nullopt;
    ParsedModule out;
    Module& m = out.module;
    m.pos = f->pos();
    if (r_.require(*f, "type", "a module")) {
        m.type = r_.text(*f->find("type"), "type").value_or("");
        m.type_pos = pos_of(*f->find("type"));
    }
    if (r_.require(*f, "ident", "a module")) m.module_ident = r_.integer<std::uint32_t>(*f->find("ident"), "ident").value_or(0);
    r_.optional_text(*f, "class", m.module_class);
    r_.optional_integer(*f, "pdo_group", m.module_pdo_group);
    extras(*f, "type_xml", m.type_extras);
    if (r_.require(*f, "name", "a module")) m.names = names_of(*f, "name");
    images(*f, m.images);
    if (const Node* n = f->find("profile")) m.profile = profile(*n);
    ObjectNames names;
    if (f->has("objects") || f->has("data_types") || f->has("dictionary_xml")) {
        if (!m.profile) {
            Profile p;
            p.pos = m.pos;
            m.profile = std::move(p);
        }
        Dictionary dict;
        dict.pos = f->find("objects") ? pos_of(*f->find("objects")) : m.pos;
        names = dictionary(*f, dict);
        m.profile->dictionary = std::move(dict);
    }
    if (const Node* n = f->find("mailbox")) m.mailbox = mailbox(*n, Context::module_mailbox, nullptr, names);
    if (const Node* n = f->find("init")) {
        if (!m.mailbox || !m.mailbox->coe)
            r_.error(*f->key_node("init"), "yaml-missing-key", "'init' holds CoE InitCmds; the module needs 'mailbox: {coe: …}'");
        else
            init_cmds(*n, MailboxProtocol::coe, names, m.mailbox->coe->init_cmds, &out.intent.init_values);
    }
    if (const Node* n = f->find("rxpdo")) m.rx_pdos = pdos(*n, PdoDirection::rx, names, &out.intent.rx_assign);
    if (const Node* n = f->find("txpdo")) m.tx_pdos = pdos(*n, PdoDirection::tx, names, &out.intent.tx_assign);
    r_.optional_text(*f, "dc_op_mode", m.dc_op_mode_name);
    if (const Node* n = f->find("derive")) out.intent.options = derive_options(*n, true);
    extras(*f, "xml", m.extras);
    return out;
}

std::optional<std::uint32_t> SourceParser::module_ident(const Node& node, const std::vector<ParsedModule>& modules,
                                                        std::string_view what) {
    if (!node.IsScalar()) {
        r_.error(node, "yaml-type", "'" + std::string(what) + "' names a module by its type or its ident");
        return std::nullopt;
    }
    const ParsedNumber n = parse_number(node.Scalar());
    if (n.ok()) return r_.integer<std::uint32_t>(node, what);
    std::vector<std::string_view> types;
    for (const auto& m : modules) {
        if (m.module.type == node.Scalar()) return m.module.module_ident;
        types.push_back(m.module.type);
    }
    std::string message = "'" + std::string(what) + "': no module has the type '" + node.Scalar() + "'";
    message += did_you_mean(node.Scalar(), types);
    r_.error(node, "yaml-reference", message);
    return std::nullopt;
}

std::optional<Slots> SourceParser::slots(const Node& node, const std::vector<ParsedModule>& modules) {
    Slots s;
    s.pos = pos_of(node);
    Node list;
    if (node.IsSequence()) {
        list = node;
    } else {
        const auto f = r_.mapping(node, Context::slots, "slots");
        if (!f) return std::nullopt;
        if (const Node* n = f->find("list")) list = *n;
        r_.optional_integer(*f, "max_slot_count", s.max_slot_count);
        r_.optional_integer(*f, "max_slot_group_count", s.max_slot_group_count);
        r_.optional_integer(*f, "slot_pdo_increment", s.slot_pdo_increment);
        r_.optional_integer(*f, "slot_group_pdo_increment", s.slot_group_pdo_increment);
        r_.optional_integer(*f, "slot_index_increment", s.slot_index_increment);
        r_.optional_integer(*f, "slot_group_index_increment", s.slot_group_index_increment);
        extras(*f, "xml", s.extras);
    }
    if (!list.IsDefined() || list.IsNull()) return s;
    const auto items = r_.sequence(list, "slots");
    if (!items) return s;
    for (const auto& item : *items) {
        const auto f = r_.mapping(item, Context::slot, "a slot");
        if (!f) continue;
        Slot slot;
        slot.pos = f->pos();
        slot.names = names_of(*f, "name");
        if (const Node* n = f->find("modules")) {
            if (auto ms = r_.sequence(*n, "modules")) {
                for (const auto& m : *ms) {
                    SlotModuleIdent id;
                    id.pos = pos_of(m);
                    if (m.IsMap()) {
                        const auto mf = r_.mapping(m, Context::slot_module, "a slot module");
                        if (!mf || !r_.require(*mf, "module", "a slot module")) continue;
                        auto v = module_ident(*mf->find("module"), modules, "module");
                        if (!v) continue;
                        id.value = *v;
                        if (const Node* dn = mf->find("default")) id.default_ident = module_ident(*dn, modules, "default");
                    } else {
                        auto v = module_ident(m, modules, "modules");
                        if (!v) continue;
                        id.value = *v;
                    }
                    slot.module_idents.push_back(id);
                }
            }
        }
        if (const Node* n = f->find("module_classes")) {
            if (auto mcs = r_.sequence(*n, "module_classes")) {
                for (const auto& mc : *mcs) {
                    const auto cf = r_.mapping(mc, Context::slot_module_class, "a module class");
                    if (!cf || !r_.require(*cf, "class", "a module class")) continue;
                    SlotModuleClass c;
                    c.pos = cf->pos();
                    c.class_name = r_.text(*cf->find("class"), "class").value_or("");
                    r_.optional_integer(*cf, "vendor_id", c.vendor_id);
                    c.names = names_of(*cf, "name");
                    extras(*cf, "xml", c.extras);
                    slot.module_classes.push_back(std::move(c));
                }
            }
        }
        if (slot.module_idents.empty() == slot.module_classes.empty())
            r_.error(f->node(), "yaml-missing-key", "a slot lists either 'modules' or 'module_classes' (ETG.2000 SlotType)");
        if (const Node* n = f->find("default")) slot.default_ident = module_ident(*n, modules, "default");
        if (const Node* n = f->find("fallback")) slot.fallback = module_ident(*n, modules, "fallback");
        r_.optional_integer(*f, "slot_group", slot.slot_group);
        // A slot without counts takes at most one module and may stay empty.
        slot.min_instances = 0;
        slot.max_instances = 1;
        if (const Node* n = f->find("min_instances")) slot.min_instances = r_.integer<std::uint32_t>(*n, "min_instances").value_or(0);
        if (const Node* n = f->find("max_instances")) slot.max_instances = r_.integer<std::uint32_t>(*n, "max_instances").value_or(1);
        if (slot.min_instances > slot.max_instances)
            r_.error(f->node(), "yaml-value", "'min_instances' is larger than 'max_instances'");
        r_.optional_integer(*f, "slot_pdo_increment", slot.slot_pdo_increment);
        r_.optional_integer(*f, "slot_group_pdo_increment", slot.slot_group_pdo_increment);
        r_.optional_integer(*f, "slot_index_increment", slot.slot_index_increment);
        r_.optional_integer(*f, "slot_group_index_increment", slot.slot_group_index_increment);
        images(*f, slot.images);
        extras(*f, "xml", slot.extras);
        s.slots.push_back(std::move(slot));
    }
    return s;
}

}  // namespace esi::yaml
