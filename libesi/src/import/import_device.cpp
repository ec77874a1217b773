// One entry of `devices:`: identity, names, physics, profile and dictionary, EEPROM settings,
// mailbox and InitCmds, SMs, FMMUs, sync units, PDOs, DC, slots and the `derive:` switches that
// match the plan.

#include "import/import_writer.hpp"

namespace esi::import_detail {

YNode ImportWriter::dc_time(const DcTime& t) {
    YNode m = YNode::map();
    m.set("value", YNode::integer(t.value));
    if (t.factor) m.set("factor", YNode::integer(*t.factor));
    if (t.input) m.set("input", YNode::boolean(*t.input));
    if (t.output_delay_time) m.set("output_delay_time", YNode::integer(*t.output_delay_time));
    if (t.input_delay_time) m.set("input_delay_time", YNode::integer(*t.input_delay_time));
    return m;
}

YNode ImportWriter::dc(const Dc& dc) {
    YNode m = YNode::map();
    YNode modes = YNode::seq();
    for (const auto& mode : dc.op_modes) {
        YNode x = YNode::map();
        x.set("name", YNode::text(mode.name));
        if (mode.desc) x.set("description", YNode::text(*mode.desc));
        if (mode.has_assign_activate) {
            if (mode.assign_activate > 0xFFFF) warn("Dc/OpMode[" + mode.name + "]/AssignActivate", "above 0xFFFF cannot be written");
            x.set("assign_activate", YNode::hex(mode.assign_activate, 4));
        }
        if (mode.cycle_time_sync0) x.set("cycle_time_sync0", dc_time(*mode.cycle_time_sync0));
        if (mode.shift_time_sync0) x.set("shift_time_sync0", dc_time(*mode.shift_time_sync0));
        if (mode.cycle_time_sync1) x.set("cycle_time_sync1", dc_time(*mode.cycle_time_sync1));
        if (mode.shift_time_sync1) x.set("shift_time_sync1", dc_time(*mode.shift_time_sync1));
        set_extras(x, "xml", mode.extras);
        modes.push(std::move(x));
    }
    m.set("op_modes", std::move(modes));
    if (dc.unknown_frmw) m.set("unknown_frmw", YNode::boolean(*dc.unknown_frmw));
    if (dc.unknown_64bit) m.set("unknown_64bit", YNode::boolean(*dc.unknown_64bit));
    if (dc.external_ref_clock) m.set("external_ref_clock", YNode::boolean(*dc.external_ref_clock));
    if (dc.potential_reference_clock) m.set("potential_reference_clock", YNode::boolean(*dc.potential_reference_clock));
    if (dc.time_loop_control_only) m.set("time_loop_control_only", YNode::boolean(*dc.time_loop_control_only));
    set_extras(m, "xml", dc.extras);
    return m;
}

const EscPreset* ImportWriter::esc_preset_of(const Eeprom& e) {
    // Only an exact match: `esc:` must give back the same ConfigData, ByteSize and BootStrap.
    if (e.data || !e.config_data || !e.byte_size) return nullptr;
    const auto config = e.config_data->bytes();
    if (!config) return nullptr;
    std::vector<std::uint8_t> boot;
    if (e.boot_strap) {
        const auto b = e.boot_strap->bytes();
        if (!b) return nullptr;
        boot = *b;
    }
    return match_esc_preset(*config, *e.byte_size, boot);
}

YNode ImportWriter::eeprom(const Eeprom& preset_or_not, const std::string& path) {
    YNode m = YNode::map();
    Eeprom e = preset_or_not;
    if (esc_preset_of(e)) {
        // `esc:` stands for these three (docs/yaml-format.md, ESC presets).
        e.byte_size.reset();
        e.config_data.reset();
        e.boot_strap.reset();
    }
    auto hex_field = [&](const char* key, const std::optional<HexData>& h) {
        if (!h) return;
        if (valid_hex(*h)) m.set(key, hex_data(*h));
        else warn(path + "/Eeprom/" + key, "'" + h->text + "' is not hex bytes; dropped");
    };
    if (e.byte_size) {
        if (*e.byte_size < 128 || *e.byte_size > 0x7FFFFFFF) warn(path + "/Eeprom/ByteSize", "out of the range the format takes (128..)");
        m.set("size", YNode::unsigned_integer(*e.byte_size));
    }
    hex_field("config_data", e.config_data);
    if (e.boot_strap && e.boot_strap->byte_length() != 8) warn(path + "/Eeprom/BootStrap", "not 8 bytes");
    hex_field("boot_strap", e.boot_strap);
    hex_field("data", e.data);
    if (!e.categories.empty()) {
        YNode list = YNode::seq();
        for (const auto& c : e.categories) {
            YNode x = YNode::map();
            x.set("number", YNode::unsigned_integer(c.cat_no));
            if (c.data) {
                if (valid_hex(*c.data)) x.set("data", hex_data(*c.data));
                else warn(path + "/Eeprom/Category", "data is not hex bytes; dropped");
            }
            if (c.data_string) x.set("data_string", YNode::text(*c.data_string));
            if (c.data_uint) x.set("data_uint", YNode::unsigned_integer(*c.data_uint));
            if (c.data_udint) x.set("data_udint", YNode::unsigned_integer(*c.data_udint));
            if (c.preserve_online_data) x.set("preserve_online_data", YNode::boolean(*c.preserve_online_data));
            set_extras(x, "xml", c.extras);
            list.push(std::move(x));
        }
        m.set("categories", std::move(list));
    }
    if (e.assign_to_pdi) m.set("assign_to_pdi", YNode::boolean(*e.assign_to_pdi));
    set_extras(m, "xml", e.extras);
    return m;
}

YNode ImportWriter::device(const Device& d, const EtherCATInfo& info, const OmitPlan& plan) {
    std::string path = "Device[" + d.type.text + "]";
    if (d.type.product_code) path = "Device[" + hex_text(*d.type.product_code, 8) + ":" + hex_text(d.type.revision_no.value_or(0), 8) + "]";
    YNode m = YNode::map();
    m.set("type", YNode::text(d.type.text));
    // A passive terminal has no identity to write; the source leaves both keys out as the file does.
    if (!is_passive_terminal(d)) {
        if (!d.type.product_code) warn(path + "/Type@ProductCode", "missing; the YAML format requires it");
        if (!d.type.revision_no) warn(path + "/Type@RevisionNo", "missing; the YAML format requires it");
        m.set("product_code", YNode::hex(d.type.product_code.value_or(0), 8));
        m.set("revision", YNode::hex(d.type.revision_no.value_or(0), 8));
    }
    if (d.type.serial_no) m.set("serial_no", YNode::hex(*d.type.serial_no, 8));
    if (d.type.tc_cfg_mode_safe_op) m.set("tc_cfg_mode_safe_op", YNode::boolean(*d.type.tc_cfg_mode_safe_op));
    set_extras(m, "type_xml", d.type.extras);
    names(m, "name", d.names, path, true);
    names(m, "comment", d.comments, path);
    names(m, "url", d.urls, path);
    if (d.group_type) m.set("group", YNode::text(*d.group_type));
    else m.set("group", YNode::raw("null"));  // no GroupType, as in the file
    m.set("physics", YNode::text(d.physics));
    if (d.invisible) m.set("invisible", YNode::boolean(*d.invisible));
    images(m, d.images);

    const Dictionary* dict = nullptr;
    if (!d.profiles.empty()) {
        for (std::size_t i = 1; i < d.profiles.size(); ++i)
            if (d.profiles[i].dictionary) warn(path + "/Profile[" + std::to_string(i + 1) + "]", "a Dictionary outside the first Profile is dropped");
        if (d.profiles.size() == 1) {
            const Profile& p = d.profiles.front();
            if (p.profile_no && !p.add_info && !p.channel && !p.dictionary_file && p.extras.empty())
                m.set("profile", YNode::integer(*p.profile_no));
            else
                m.set("profile", profile(p));
        } else {
            YNode list = YNode::seq();
            for (const auto& p : d.profiles) list.push(profile(p));
            m.set("profile", std::move(list));
        }
        if (d.profiles.front().dictionary) dict = &*d.profiles.front().dictionary;
    }
    if (dict) dictionary(m, *dict, path, plan, &d);

    if (d.eeprom) {
        const EscPreset* preset = esc_preset_of(*d.eeprom);
        if (preset) m.set("esc", YNode::text(std::string(preset->name)));
        YNode e = eeprom(*d.eeprom, path);
        if (!e.empty() || !preset) m.set("eeprom", std::move(e));
    }
    if (d.mailbox) {
        m.set("mailbox", mailbox(*d.mailbox, &d, plan, path + "/Mailbox"));
        if (d.mailbox->coe && !d.mailbox->coe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < d.mailbox->coe->init_cmds.size(); ++i)
                list.push(init_cmd(d.mailbox->coe->init_cmds[i], MailboxProtocol::coe, path + "/Mailbox/CoE/InitCmd[" + std::to_string(i + 1) + "]"));
            m.set("init", std::move(list));
        }
    }
    if (!plan.sms && !d.sms.empty()) {
        YNode list = YNode::seq();
        for (const auto& sm : d.sms) {
            YNode x = YNode::map();
            x.set("type", YNode::text(sm.type));
            if (sm.start_address) x.set("address", YNode::hex(*sm.start_address, 4));
            if (sm.control_byte) x.set("control_byte", YNode::hex(*sm.control_byte, 2));
            if (sm.default_size) x.set("size", YNode::unsigned_integer(*sm.default_size));
            if (sm.min_size) x.set("min_size", YNode::unsigned_integer(*sm.min_size));
            if (sm.max_size) x.set("max_size", YNode::unsigned_integer(*sm.max_size));
            if (sm.enable) x.set("enable", YNode::unsigned_integer(*sm.enable));
            if (sm.is_virtual) x.set("virtual", YNode::boolean(*sm.is_virtual));
            if (sm.watchdog) x.set("watchdog", YNode::boolean(*sm.watchdog));
            if (sm.op_only) x.set("op_only", YNode::boolean(*sm.op_only));
            if (sm.fixed_assignment) x.set("fixed_assignment", YNode::boolean(*sm.fixed_assignment));
            if (sm.one_byte_mode) x.set("one_byte_mode", YNode::boolean(*sm.one_byte_mode));
            set_extras(x, "xml", sm.extras);
            list.push(std::move(x));
        }
        m.set("sms", std::move(list));
    }
    if (!plan.fmmus && !d.fmmus.empty()) {
        YNode list = YNode::seq();
        for (const auto& f : d.fmmus) {
            if (!f.sm && !f.su && !f.op_only && f.extras.empty()) {
                list.push(YNode::text(f.type));
                continue;
            }
            YNode x = YNode::map();
            x.set("type", YNode::text(f.type));
            if (f.sm) x.set("sm", YNode::unsigned_integer(*f.sm));
            if (f.su) x.set("su", YNode::unsigned_integer(*f.su));
            if (f.op_only) x.set("op_only", YNode::boolean(*f.op_only));
            set_extras(x, "xml", f.extras);
            list.push(std::move(x));
        }
        m.set("fmmus", std::move(list));
    }
    if (!d.sus.empty()) {
        YNode list = YNode::seq();
        for (const auto& su : d.sus) {
            YNode x = YNode::map();
            x.set("text", YNode::text(su.text));
            if (su.separate_su) x.set("separate_su", YNode::boolean(*su.separate_su));
            if (su.separate_frame) x.set("separate_frame", YNode::boolean(*su.separate_frame));
            if (su.depend_on_input_state) x.set("depend_on_input_state", YNode::boolean(*su.depend_on_input_state));
            if (su.frame_repeat_support) x.set("frame_repeat_support", YNode::boolean(*su.frame_repeat_support));
            set_extras(x, "xml", su.extras);
            list.push(std::move(x));
        }
        m.set("sync_units", std::move(list));
    }
    for (const auto* pdos : {&d.rx_pdos, &d.tx_pdos}) {
        if (pdos->empty()) continue;
        YNode list = YNode::seq();
        for (const auto& p : *pdos) list.push(pdo(p, plan, path));
        m.set(pdos == &d.rx_pdos ? "rxpdo" : "txpdo", std::move(list));
    }
    if (d.dc) m.set("dc", dc(*d.dc));
    if (d.slots) m.set("slots", slots(*d.slots, path));
    if (!plan.any()) {
        m.set("derive", YNode::boolean(false));
    } else {
        DeriveOptions o = plan.derive_options();
        // A group is derived only for a GroupType no group declares; the file's groups are all written.
        o.groups = !d.group_type || info.find_group(*d.group_type) != nullptr;
        YNode x = YNode::map();
        auto off = [&](const char* key, bool on) {
            if (!on) x.set(key, YNode::boolean(false));
        };
        off("groups", o.groups);
        off("mailbox", o.mailbox);
        off("sync_managers", o.sync_managers);
        off("fmmus", o.fmmus);
        off("pdo_assignment", o.pdo_assignment);
        off("pdo_entries", o.pdo_entries);
        off("mapping_objects", o.mapping_objects);
        off("assignment_objects", o.assignment_objects);
        off("sm_types_object", o.sm_types_object);
        off("identity_object", o.identity_object);
        off("device_type_object", o.device_type_object);
        off("data_types", o.data_types);
        if (!x.empty()) m.set("derive", std::move(x));
    }
    set_extras(m, "xml", d.extras);
    return m;
}

}  // namespace esi::import_detail
