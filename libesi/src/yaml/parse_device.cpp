// One entry of `devices:`: identity, names, physics, the object dictionary, mailbox, SMs, FMMUs,
// PDOs, InitCmds, DC, slots, EEPROM settings and the device's own limits.

#include <algorithm>

#include "esi/model/esc_preset.hpp"
#include "esi/yaml/limits.hpp"
#include "esi/text_distance.hpp"
#include "yaml/source_parser.hpp"

namespace esi::yaml {

namespace {

bool known_word(std::string_view word, std::span<const std::string_view> words) {
    return std::find(words.begin(), words.end(), word) != words.end();
}

}  // namespace

Limits SourceParser::limits(const Node& node) { return read_limits(r_, node); }

std::optional<Eeprom> SourceParser::eeprom(const Node& node) {
    const auto f = r_.mapping(node, Context::eeprom, "eeprom");
    if (!f) return std::nullopt;
    Eeprom e;
    e.pos = f->pos();
    if (const Node* n = f->find("size")) {
        e.byte_size = r_.integer<std::uint32_t>(*n, "size", 128, 0x7FFFFFFF);
        e.byte_size_pos = pos_of(*n);
    }
    if (const Node* n = f->find("config_data")) e.config_data = r_.hex(*n, "config_data");
    if (const Node* n = f->find("boot_strap")) {
        if (n->IsMap()) {
            // ETG.2000 BootStrap: 8 bytes, four little-endian words (out offset, out size, in offset, in size).
            const auto bf = r_.mapping(*n, Context::boot_strap, "boot_strap");
            if (bf) {
                std::vector<std::uint8_t> bytes;
                for (const char* k : {"out_address", "out_size", "in_address", "in_size"}) {
                    std::uint32_t v = 0;
                    if (r_.require(*bf, k, "boot_strap")) v = r_.integer<std::uint32_t>(*bf->find(k), k, 0, 0xFFFF).value_or(0);
                    bytes.push_back(static_cast<std::uint8_t>(v & 0xFF));
                    bytes.push_back(static_cast<std::uint8_t>(v >> 8));
                }
                e.boot_strap = HexData::from_bytes(bytes);
                e.boot_strap->pos = pos_of(*n);
            }
        } else if (auto h = r_.hex(*n, "boot_strap")) {
            if (h->byte_length() != 8) r_.error(*n, "yaml-value", "'boot_strap' is 8 bytes (out address, out size, in address, in size)");
            e.boot_strap = h;
        }
    }
    if (const Node* n = f->find("data")) {
        e.data = r_.hex(*n, "data");
        for (const char* k : {"size", "config_data", "boot_strap"})
            if (f->has(k))
                r_.error(*f->key_node(k), "yaml-conflict",
                         "'data' is a complete EEPROM image; it excludes '" + std::string(k) + "' (ETG.2000 Eeprom: Data or ByteSize/ConfigData/BootStrap)");
    }
    if (const Node* n = f->find("categories")) {
        if (auto items = r_.sequence(*n, "categories")) {
            for (const auto& item : *items) {
                const auto cf = r_.mapping(item, Context::eeprom_category, "a category");
                if (!cf) continue;
                EepromCategory c;
                c.pos = cf->pos();
                if (r_.require(*cf, "number", "a category")) {
                    c.cat_no = r_.integer<std::uint32_t>(*cf->find("number"), "number", 0, 0xFFFF).value_or(0);
                    c.cat_no_pos = pos_of(*cf->find("number"));
                }
                if (const Node* d = cf->find("data")) c.data = r_.hex(*d, "data");
                r_.optional_text(*cf, "data_string", c.data_string);
                r_.optional_integer(*cf, "data_uint", c.data_uint);
                r_.optional_integer(*cf, "data_udint", c.data_udint);
                r_.optional_bool(*cf, "preserve_online_data", c.preserve_online_data);
                extras(*cf, "xml", c.extras);
                e.categories.push_back(std::move(c));
            }
        }
    }
    r_.optional_bool(*f, "assign_to_pdi", e.assign_to_pdi);
    extras(*f, "xml", e.extras);
    return e;
}

void SourceParser::esc_preset(const Node& node, Device& d) {
    const auto name = r_.text(node, "esc");
    if (!name) return;
    const EscPreset* preset = find_esc_preset(*name);
    if (!preset) {
        std::vector<std::string_view> names;
        for (const auto& p : esc_presets()) names.push_back(p.name);
        const std::string hint = did_you_mean(*name, names);
        r_.error(node, "yaml-value",
                 "'" + *name + "' is not an ESC preset" + (hint.empty() ? std::string(".") : hint) + " The presets are " + esc_preset_names() +
                     "; an ESC not listed takes 'eeprom: {config_data: …}' from its datasheet");
        return;
    }
    if (d.eeprom && d.eeprom->data) {
        r_.error(node, "yaml-conflict", "'eeprom.data' is a complete EEPROM image; it excludes 'esc' (the preset's ConfigData would not be used)");
        return;
    }
    // What the source states explicitly wins over the preset (docs/yaml-format.md).
    if (!d.eeprom) {
        d.eeprom.emplace();
        d.eeprom->pos = pos_of(node);
    }
    Eeprom& e = *d.eeprom;
    if (!e.byte_size) {
        e.byte_size = preset->eeprom_bytes;
        e.byte_size_pos = pos_of(node);
    }
    if (!e.config_data) {
        e.config_data = HexData::from_bytes(preset->config_bytes());
        e.config_data->pos = pos_of(node);
    }
    if (!e.boot_strap && !preset->boot_strap.empty()) {
        e.boot_strap = HexData::from_bytes(preset->boot_strap_bytes());
        e.boot_strap->pos = pos_of(node);
    }
}

std::vector<SyncManager> SourceParser::sync_managers(const Node& node, std::vector<SourcePos>& size_pos) {
    static constexpr std::string_view types[] = {"MBoxOut", "MBoxIn", "Outputs", "Inputs"};
    std::vector<SyncManager> out;
    const auto items = r_.sequence(node, "sms");
    if (!items) return out;
    for (const auto& item : *items) {
        SyncManager sm;
        sm.pos = pos_of(item);
        SourcePos size_at;
        const auto f = r_.mapping(item, Context::sm, "an SM");
        if (f) {
            if (const Node* n = f->find("type")) {
                sm.type = r_.text(*n, "type").value_or("");
                if (!sm.type.empty() && !known_word(sm.type, types)) {
                    // A warning: ETG.2000 gives Sm a free text and vendor files use others (DynamicOutputs …).
                    std::string message = "SM type '" + sm.type + "' is not MBoxOut, MBoxIn, Outputs or Inputs";
                    message += did_you_mean(sm.type, types);
                    r_.warning(pos_of(*n), "yaml-value", message + "; kept as written");
                }
            }
            r_.optional_integer<std::uint32_t>(*f, "address", sm.start_address, 0, 0xFFFF);
            r_.optional_integer<std::uint32_t>(*f, "control_byte", sm.control_byte, 0, 0xFF);
            if (const Node* n = f->find("size")) {
                sm.default_size = r_.integer<std::uint32_t>(*n, "size", 0, 0xFFFF);
                size_at = pos_of(*n);
            }
            r_.optional_integer<std::uint32_t>(*f, "min_size", sm.min_size, 0, 0xFFFF);
            r_.optional_integer<std::uint32_t>(*f, "max_size", sm.max_size, 0, 0xFFFF);
            if (const Node* n = f->find("enable")) {
                if (n->IsScalar() && (n->Scalar() == "true" || n->Scalar() == "false")) sm.enable = n->Scalar() == "true" ? 1u : 0u;
                else sm.enable = r_.integer<std::uint32_t>(*n, "enable", 0, 0xFF);
            }
            r_.optional_bool(*f, "virtual", sm.is_virtual);
            r_.optional_bool(*f, "watchdog", sm.watchdog);
            r_.optional_bool(*f, "op_only", sm.op_only);
            r_.optional_bool(*f, "fixed_assignment", sm.fixed_assignment);
            r_.optional_bool(*f, "one_byte_mode", sm.one_byte_mode);
            extras(*f, "xml", sm.extras);
        }
        size_pos.push_back(size_at);
        out.push_back(std::move(sm));
    }
    return out;
}

std::vector<Fmmu> SourceParser::fmmus(const Node& node) {
    static constexpr std::string_view types[] = {"Outputs", "Inputs", "MBoxState", "DynamicInputs", "DynamicOutputs"};
    std::vector<Fmmu> out;
    const auto items = r_.sequence(node, "fmmus");
    if (!items) return out;
    for (const auto& item : *items) {
        Fmmu fm;
        fm.pos = pos_of(item);
        const Node* type_node = nullptr;
        std::optional<Fields> f;
        if (item.IsScalar()) {
            type_node = &item;
        } else if ((f = r_.mapping(item, Context::fmmu, "an FMMU"))) {
            type_node = f->find("type");
            r_.optional_integer<std::uint32_t>(*f, "sm", fm.sm, 0, 31);
            r_.optional_integer<std::uint32_t>(*f, "su", fm.su, 0, 255);
            r_.optional_bool(*f, "op_only", fm.op_only);
            extras(*f, "xml", fm.extras);
        } else {
            continue;
        }
        if (type_node) {
            fm.type = r_.text(*type_node, "type").value_or("");
            if (!fm.type.empty() && !known_word(fm.type, types)) {
                // A warning, as for SM types: vendor files use their own texts and an import keeps them.
                std::string message = "FMMU type '" + fm.type + "' is not Outputs, Inputs, MBoxState, DynamicInputs or DynamicOutputs";
                message += did_you_mean(fm.type, types);
                r_.warning(pos_of(*type_node), "yaml-value", message + "; kept as written");
            }
        }
        out.push_back(std::move(fm));
    }
    return out;
}

std::vector<SyncUnit> SourceParser::sync_units(const Node& node) {
    std::vector<SyncUnit> out;
    const auto items = r_.sequence(node, "sync_units");
    if (!items) return out;
    for (const auto& item : *items) {
        const auto f = r_.mapping(item, Context::sync_unit, "a sync unit");
        if (!f) continue;
        SyncUnit su;
        su.pos = f->pos();
        if (const Node* n = f->find("text")) su.text = r_.text(*n, "text").value_or("");
        r_.optional_bool(*f, "separate_su", su.separate_su);
        r_.optional_bool(*f, "separate_frame", su.separate_frame);
        r_.optional_bool(*f, "depend_on_input_state", su.depend_on_input_state);
        r_.optional_bool(*f, "frame_repeat_support", su.frame_repeat_support);
        extras(*f, "xml", su.extras);
        out.push_back(std::move(su));
    }
    return out;
}

std::optional<DcTime> SourceParser::dc_time(const Node& node, bool shift) {
    DcTime t;
    t.pos = pos_of(node);
    if (node.IsScalar()) {
        t.value = r_.integer<std::int64_t>(node, "time (ns)").value_or(0);
        return t;
    }
    const auto f = r_.mapping(node, Context::dc_time, "a DC time");
    if (!f) return std::nullopt;
    if (const Node* n = f->find("value")) t.value = r_.integer<std::int64_t>(*n, "value").value_or(0);
    r_.optional_integer(*f, "factor", t.factor);
    if (const Node* n = f->find("input")) {
        if (!shift) r_.error(*f->key_node("input"), "yaml-value", "'input' applies to shift times only");
        t.input = r_.boolean(*n, "input");
    }
    r_.optional_integer(*f, "output_delay_time", t.output_delay_time);
    r_.optional_integer(*f, "input_delay_time", t.input_delay_time);
    return t;
}

std::optional<Dc> SourceParser::dc(const Node& node) {
    Dc dc;
    dc.pos = pos_of(node);
    Node modes;
    if (node.IsSequence()) {
        modes = node;
    } else {
        const auto f = r_.mapping(node, Context::dc, "dc");
        if (!f) return std::nullopt;
        if (const Node* n = f->find("op_modes")) modes = *n;
        r_.optional_bool(*f, "unknown_frmw", dc.unknown_frmw);
        r_.optional_bool(*f, "unknown_64bit", dc.unknown_64bit);
        r_.optional_bool(*f, "external_ref_clock", dc.external_ref_clock);
        r_.optional_bool(*f, "potential_reference_clock", dc.potential_reference_clock);
        r_.optional_bool(*f, "time_loop_control_only", dc.time_loop_control_only);
        extras(*f, "xml", dc.extras);
    }
    if (modes.IsDefined() && !modes.IsNull()) {
        if (auto items = r_.sequence(modes, "op_modes")) {
            for (const auto& item : *items) {
                const auto f = r_.mapping(item, Context::op_mode, "a DC op mode");
                if (!f) continue;
                DcOpMode m;
                m.pos = f->pos();
                if (r_.require(*f, "name", "a DC op mode")) m.name = r_.text(*f->find("name"), "name").value_or("");
                r_.optional_text(*f, "description", m.desc);
                if (const Node* n = f->find("assign_activate")) {
                    m.assign_activate_pos = pos_of(*n);
                    if (auto v = r_.integer<std::uint32_t>(*n, "assign_activate", 0, 0xFFFF)) {
                        m.assign_activate = *v;
                        m.has_assign_activate = true;
                    }
                }
                if (const Node* n = f->find("cycle_time_sync0")) m.cycle_time_sync0 = dc_time(*n, false);
                if (const Node* n = f->find("shift_time_sync0")) m.shift_time_sync0 = dc_time(*n, true);
                if (const Node* n = f->find("cycle_time_sync1")) m.cycle_time_sync1 = dc_time(*n, false);
                if (const Node* n = f->find("shift_time_sync1")) m.shift_time_sync1 = dc_time(*n, true);
                extras(*f, "xml", m.extras);
                dc.op_modes.push_back(std::move(m));
            }
        }
    }
    return dc;
}

std::optional<ParsedDevice> SourceParser::device(const Node& node, std::optional<std::uint32_t> vendor_id,
                                                 const std::vector<ParsedModule>& modules, std::size_t group_count,
                                                 const std::string* only_group) {
    const auto f = r_.mapping(node, Context::device, "a device");
    if (!f) return std::nullopt;
    ParsedDevice out;
    Device& d = out.device;
    DeviceIntent& intent = out.intent;
    intent.vendor_id = vendor_id;
    d.pos = f->pos();

    // Identity (Device/Type).
    if (r_.require(*f, "type", "a device")) {
        d.type.text = r_.text(*f->find("type"), "type").value_or("");
        d.type.pos = pos_of(*f->find("type"));
    }
    // A passive terminal (Beckhoff EL9xxx end and supply terminals) has no ESC and so no EtherCAT
    // identity: its Type has neither ProductCode nor RevisionNo. Without both keys and without any
    // key that needs an ESC, the device is such a terminal (docs/yaml-format.md, "Devices").
    static constexpr std::string_view esc_keys[] = {"mailbox", "objects", "data_types", "dictionary_xml", "sms",  "fmmus",
                                                    "sync_units", "rxpdo", "txpdo", "init", "dc", "slots", "eeprom", "esc", "profile"};
    const bool passive = !f->has("product_code") && !f->has("revision") &&
                         std::none_of(std::begin(esc_keys), std::end(esc_keys), [&](std::string_view k) { return f->has(k); });
    if (!passive) {
        if (r_.require(*f, "product_code", "a device"))
            d.type.product_code = r_.integer<std::uint32_t>(*f->find("product_code"), "product_code");
        if (r_.require(*f, "revision", "a device")) d.type.revision_no = r_.integer<std::uint32_t>(*f->find("revision"), "revision");
    }
    r_.optional_integer(*f, "serial_no", d.type.serial_no);
    r_.optional_bool(*f, "tc_cfg_mode_safe_op", d.type.tc_cfg_mode_safe_op);
    extras(*f, "type_xml", d.type.extras);

    if (r_.require(*f, "name", "a device")) d.names = names_of(*f, "name");
    d.comments = names_of(*f, "comment");
    d.urls = names_of(*f, "url");
    if (const Node* n = f->find("group"); n && n->IsNull()) {
        // `group: null`: no GroupType at all, as some imported files have (esi-gen --import).
    } else if (n) {
        d.group_type = r_.text(*n, "group");
        d.group_type_pos = pos_of(*n);
    } else if (group_count == 1 && only_group) {
        d.group_type = *only_group;
        d.group_type_pos = d.pos;
    } else if (group_count == 0 && !d.type.text.empty()) {
        // Nothing declared and nothing named: the device's type is its group, and derivation
        // adds that Group (docs/yaml-format.md, "Devices").
        d.group_type = d.type.text;
        d.group_type_pos = d.type.pos;
    } else {
        r_.error(f->node(), "yaml-missing-key",
                 group_count == 0 ? "a device needs 'group' (its Group type) or a 'type' to derive it from"
                                  : "a device needs 'group' when several groups are declared (it names one group's 'type')");
    }
    // Two MII ports is the usual device; an E-Bus terminal writes "KK".
    if (const Node* n = f->find("physics")) {
        d.physics = r_.text(*n, "physics").value_or("");
        for (char c : d.physics)
            if (c != 'Y' && c != 'H' && c != 'K' && c != ' ') {
                // A warning: vendor files use other letters, and an imported file keeps them.
                r_.warning(pos_of(*n), "yaml-value",
                           "'physics' has one letter per port: Y or H (MII), K (E-Bus) or a blank (no port), not '" + d.physics +
                               "'; kept as written");
                break;
            }
    } else {
        d.physics = "YY";
    }
    r_.optional_bool(*f, "invisible", d.invisible);
    images(*f, d.images);

    // Profile and object dictionary.
    if (const Node* n = f->find("profile")) {
        if (n->IsSequence()) {
            for (const auto& p : *n)
                if (auto profile_value = profile(p)) d.profiles.push_back(std::move(*profile_value));
        } else if (auto p = profile(*n)) {
            d.profiles.push_back(std::move(*p));
        }
    }
    ObjectNames names;
    if (f->has("objects") || f->has("data_types") || f->has("dictionary_xml")) {
        if (d.profiles.empty()) {
            Profile p;
            p.pos = d.pos;
            d.profiles.push_back(std::move(p));
        }
        Dictionary dict;
        dict.pos = f->find("objects") ? pos_of(*f->find("objects")) : d.pos;
        names = dictionary(*f, dict);
        d.profiles.front().dictionary = std::move(dict);
    }

    if (const Node* n = f->find("mailbox")) d.mailbox = mailbox(*n, Context::mailbox, &intent.mailbox, names);
    if (const Node* n = f->find("init")) {
        if (!d.mailbox || !d.mailbox->coe) {
            r_.error(*f->key_node("init"), "yaml-missing-key", "'init' holds CoE InitCmds; the device needs 'mailbox: {coe: …}'");
        } else {
            init_cmds(*n, MailboxProtocol::coe, names, d.mailbox->coe->init_cmds, &intent.init_values);
        }
    }
    if (const Node* n = f->find("sms")) d.sms = sync_managers(*n, intent.sm_size_pos);
    if (const Node* n = f->find("fmmus")) d.fmmus = fmmus(*n);
    if (const Node* n = f->find("sync_units")) d.sus = sync_units(*n);
    if (const Node* n = f->find("rxpdo")) d.rx_pdos = pdos(*n, PdoDirection::rx, names, &intent.rx_assign);
    if (const Node* n = f->find("txpdo")) d.tx_pdos = pdos(*n, PdoDirection::tx, names, &intent.tx_assign);
    {
        // An index is one PDO, whatever its direction.
        std::map<std::uint32_t, SourcePos> rx;
        for (const auto& p : d.rx_pdos) rx.emplace(p.index, p.index_pos);
        for (const auto& p : d.tx_pdos)
            if (const auto it = rx.find(p.index); it != rx.end()) {
                Diagnostic& diag = r_.error(p.index_pos, "yaml-duplicate", "this PDO index is used by an RxPDO and a TxPDO");
                diag.notes.push_back({r_.path(), it->second, "the RxPDO"});
            }
    }
    if (const Node* n = f->find("dc")) d.dc = dc(*n);
    if (const Node* n = f->find("slots")) d.slots = slots(*n, modules);
    if (const Node* n = f->find("eeprom")) d.eeprom = eeprom(*n);
    if (const Node* n = f->find("esc")) esc_preset(*n, d);
    if (const Node* n = f->find("limits")) {
        out.limits = limits(*n);
        intent.limits = *out.limits;
    }
    if (const Node* n = f->find("derive")) intent.options = derive_options(*n, false);
    extras(*f, "xml", d.extras);
    return out;
}

}  // namespace esi::yaml
