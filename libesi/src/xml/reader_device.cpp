// ESI XML -> model: Device (DeviceType of EtherCATInfo.xsd) with its identity, FMMUs,
// SyncManagers, sync units, PDOs and their entries, Dc operation modes and Eeprom.

#include "xml/reader_context.hpp"

namespace esi::xml_reader {

void Reader::read_identity(DeviceIdentity& t, const Element n) {
    t.pos = pos_of(n);
    text(t.text, n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "ProductCode")) t.product_code = u32(a, n);
        else if (is(an, "RevisionNo")) t.revision_no = u32(a, n);
        else if (is(an, "SerialNo")) t.serial_no = u32(a, n);
        else if (is(an, "TcCfgModeSafeOp")) t.tc_cfg_mode_safe_op = boolean(a, n);
        else keep(t.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view, std::string_view previous) { keep(t.extras, c, previous); });
}

void Reader::read_device(Device& d, const Element n) {
    d.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "Physics")) d.physics = a.value;
        else if (is(an, "Invisible")) d.invisible = boolean(a, n);
        else keep(d.extras, a);
    }
    bool has_type = false;
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Type")) {
            if (has_type) d.type = {};  // a repeated Type replaces the first
            read_identity(d.type, c);
            has_type = true;
        } else if (is(name, "Name")) localized(d.names, c);
        else if (is(name, "Comment")) localized(d.comments, c);
        else if (is(name, "URL")) localized(d.urls, c);
        else if (is(name, "GroupType")) {
            text(d.group_type, c);
            d.group_type_pos = pos_of(c);
        } else if (is(name, "Profile")) read_profile(d.profiles.emplace_back(), c);
        else if (is(name, "Fmmu")) read_fmmu(d.fmmus.emplace_back(), c);
        else if (is(name, "Sm")) read_sm(d.sms.emplace_back(), c);
        else if (is(name, "Su")) read_su(d.sus.emplace_back(), c);
        else if (is(name, "RxPdo")) read_pdo(d.rx_pdos.emplace_back(), c, PdoDirection::rx);
        else if (is(name, "TxPdo")) read_pdo(d.tx_pdos.emplace_back(), c, PdoDirection::tx);
        else if (is(name, "Mailbox")) read_mailbox(d.mailbox.emplace(), c);
        else if (is(name, "Dc")) read_dc(d.dc.emplace(), c);
        else if (is(name, "Slots")) read_slots(d.slots.emplace(), c);
        else if (is(name, "Eeprom")) read_eeprom(d.eeprom.emplace(), c);
        else if (!read_image(d.images, c, name)) keep(d.extras, c, previous);
    });
    if (!has_type) missing("Device", "Type", d.pos);
}

void Reader::read_sm(SyncManager& sm, const Element n) {
    sm.pos = pos_of(n);
    text(sm.type, n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "StartAddress")) sm.start_address = u32(a, n);
        else if (is(an, "ControlByte")) sm.control_byte = u32(a, n);
        else if (is(an, "DefaultSize")) sm.default_size = u32(a, n);
        else if (is(an, "MinSize")) sm.min_size = u32(a, n);
        else if (is(an, "MaxSize")) sm.max_size = u32(a, n);
        else if (is(an, "Enable")) sm.enable = u32(a, n);
        else if (is(an, "OneByteMode")) sm.one_byte_mode = boolean(a, n);
        else if (is(an, "Virtual")) sm.is_virtual = boolean(a, n);
        else if (is(an, "Watchdog")) sm.watchdog = boolean(a, n);
        else if (is(an, "OpOnly")) sm.op_only = boolean(a, n);
        else if (is(an, "FixedAssignment")) sm.fixed_assignment = boolean(a, n);
        else keep(sm.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view, std::string_view previous) { keep(sm.extras, c, previous); });
}

void Reader::read_fmmu(Fmmu& f, const Element n) {
    f.pos = pos_of(n);
    text(f.type, n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "Sm")) f.sm = u32(a, n);
        else if (is(an, "Su")) f.su = u32(a, n);
        else if (is(an, "OpOnly")) f.op_only = boolean(a, n);
        else keep(f.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view, std::string_view previous) { keep(f.extras, c, previous); });
}

void Reader::read_su(SyncUnit& s, const Element n) {
    s.pos = pos_of(n);
    text(s.text, n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "SeparateSu")) s.separate_su = boolean(a, n);
        else if (is(an, "SeparateFrame")) s.separate_frame = boolean(a, n);
        else if (is(an, "DependOnInputState")) s.depend_on_input_state = boolean(a, n);
        else if (is(an, "FrameRepeatSupport")) s.frame_repeat_support = boolean(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view, std::string_view previous) { keep(s.extras, c, previous); });
}

void Reader::read_pdo(Pdo& p, const Element n, PdoDirection direction) {
    p.direction = direction;
    p.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "Fixed")) p.fixed = boolean(a, n);
        else if (is(an, "Mandatory")) p.mandatory = boolean(a, n);
        else if (is(an, "Virtual")) p.is_virtual = boolean(a, n);
        else if (is(an, "Sm")) p.sm = u32(a, n);
        else if (is(an, "Su")) p.su = u32(a, n);
        else if (is(an, "PdoOrder")) p.pdo_order = i32(a, n);
        else if (is(an, "OSFac")) p.os_fac = i32(a, n);
        else if (is(an, "OSMin")) p.os_min = i32(a, n);
        else if (is(an, "OSMax")) p.os_max = i32(a, n);
        else if (is(an, "OSIndexInc")) p.os_index_inc = i32(a, n);
        else if (is(an, "OverwrittenByModule")) p.overwritten_by_module = boolean(a, n);
        else if (is(an, "SRA_Parameter")) p.sra_parameter = boolean(a, n);
        else if (is(an, "SafetyPdoType")) p.safety_pdo_type = a.value;
        else if (is(an, "SafetyConnNumber")) p.safety_conn_number = i32(a, n);
        else keep(p.extras, a);
    }
    reserve_for(p.entries, n, "Entry");
    bool has_index = false;
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) {
            has_index = true;
            p.index_pos = pos_of(c);
            const std::optional<std::uint32_t> index = u32(c);
            p.index = index.value_or(0);
            p.index_invalid = !index;
            depend_on_slot(c, p.index_depend_on_slot, p.index_depend_on_slot_group);
        } else if (is(name, "Name")) localized(p.names, c);
        else if (is(name, "Exclude")) {
            PdoExclude e;
            e.pos = pos_of(c);
            e.index = u32(c).value_or(0);
            depend_on_slot(c, e.depend_on_slot, e.depend_on_slot_group);
            p.excludes.push_back(e);
        } else if (is(name, "Entry")) read_entry(p.entries.emplace_back(), c);
        else if (is(name, "ExcludedSm")) {
            if (auto v = u32(c)) p.excluded_sms.push_back(*v);
        } else keep(p.extras, c, previous);
    });
    // A pre-ETG.2000 PDO names its description with Ref= instead (kept in extras; pdo-legacy-ref).
    if (!has_index && !n.attribute("Ref")) missing(n.name(), "Index", p.pos);
}

void Reader::read_entry(PdoEntry& e, const Element n) {
    e.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "Fixed")) e.fixed = boolean(a, n);
        else keep(e.extras, a);
    }
    bool has_index = false;
    bool has_bit_len = false;
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) {
            has_index = true;
            const std::optional<std::uint32_t> index = u32(c);
            e.index = index.value_or(0);
            e.index_invalid = !index;
            e.index_pos = pos_of(c);
            depend_on_slot(c, e.index_depend_on_slot, e.index_depend_on_slot_group);
        } else if (is(name, "SubIndex")) e.subindex = u32(c);
        else if (is(name, "BitLen")) {
            has_bit_len = true;
            e.bit_len = u32(c).value_or(0);
            e.bit_len_pos = pos_of(c);
        } else if (is(name, "Name")) localized(e.names, c);
        else if (is(name, "Comment")) text(e.comment, c);
        else if (is(name, "DataType")) {
            text(e.data_type, c);
            e.data_type_pos = pos_of(c);
            for (const Attr& a : c.attributes()) {
                const std::string_view an = a.name;
                if (is(an, "DScale")) e.data_type_dscale = a.value;
                else if (is(an, "SwapData")) e.data_type_swap_data = std::string(trim(a.value));
            }
        } else keep(e.extras, c, previous);
    });
    if (!has_index) missing("Entry", "Index", e.pos);
    if (!has_bit_len) missing("Entry", "BitLen", e.pos);
}

DcTime Reader::read_dc_time(const Element n) {
    DcTime t;
    t.pos = pos_of(n);
    t.value = i64(n).value_or(0);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "Factor")) t.factor = i32(a, n);
        else if (is(an, "Input")) t.input = boolean(a, n);
        else if (is(an, "OutputDelayTime")) t.output_delay_time = i32(a, n);
        else if (is(an, "InputDelayTime")) t.input_delay_time = i32(a, n);
    }
    return t;
}

void Reader::read_op_mode(DcOpMode& m, const Element n) {
    m.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(m.extras, a);
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Name")) text(m.name, c);
        else if (is(name, "Desc")) text(m.desc, c);
        else if (is(name, "AssignActivate")) {
            m.assign_activate_pos = pos_of(c);
            if (auto v = u32(c)) {
                m.assign_activate = *v;
                m.has_assign_activate = true;
            }
        } else if (is(name, "CycleTimeSync0")) m.cycle_time_sync0 = read_dc_time(c);
        else if (is(name, "ShiftTimeSync0")) m.shift_time_sync0 = read_dc_time(c);
        else if (is(name, "CycleTimeSync1")) m.cycle_time_sync1 = read_dc_time(c);
        else if (is(name, "ShiftTimeSync1")) m.shift_time_sync1 = read_dc_time(c);
        else keep(m.extras, c, previous);
    });
}

void Reader::read_dc(Dc& dc, const Element n) {
    dc.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "UnknownFRMW")) dc.unknown_frmw = boolean(a, n);
        else if (is(an, "Unknown64Bit")) dc.unknown_64bit = boolean(a, n);
        else if (is(an, "ExternalRefClock")) dc.external_ref_clock = boolean(a, n);
        else if (is(an, "PotentialReferenceClock")) dc.potential_reference_clock = boolean(a, n);
        else if (is(an, "TimeLoopControlOnly")) dc.time_loop_control_only = boolean(a, n);
        else keep(dc.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "OpMode")) read_op_mode(dc.op_modes.emplace_back(), c);
        else keep(dc.extras, c, previous);
    });
}

void Reader::read_eeprom(Eeprom& e, const Element n) {
    e.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        if (is(a.name, "AssignToPdi")) e.assign_to_pdi = boolean(a, n);
        else keep(e.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Data")) e.data = hex(c);
        else if (is(name, "ByteSize")) {
            e.byte_size = u32(c);
            e.byte_size_pos = pos_of(c);
        } else if (is(name, "ConfigData")) e.config_data = hex(c);
        else if (is(name, "BootStrap")) e.boot_strap = hex(c);
        else if (is(name, "Category")) {
            EepromCategory cat;
            cat.pos = pos_of(c);
            for (const Attr& a : c.attributes()) {
                if (is(a.name, "PreserveOnlineData")) cat.preserve_online_data = boolean(a, c);
                else keep(cat.extras, a);
            }
            for_children(c, [&](const Element cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "CatNo")) {
                    cat.cat_no = u32(cc).value_or(0);
                    cat.cat_no_pos = pos_of(cc);
                } else if (is(cn, "Data")) cat.data = hex(cc);
                else if (is(cn, "DataString")) cat.data_string = pcdata(cc);
                else if (is(cn, "DataUINT")) cat.data_uint = u64(cc);
                else if (is(cn, "DataUDINT")) cat.data_udint = u64(cc);
                else keep(cat.extras, cc, prev);
            });
            e.categories.push_back(std::move(cat));
        } else keep(e.extras, c, previous);
    });
}

}  // namespace esi::xml_reader
