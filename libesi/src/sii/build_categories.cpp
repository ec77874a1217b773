// The SII categories the builder makes from a device (ETG.2010): General, FMMU, SyncM, DC and
// TxPDO/RxPDO, and the ESI's own Eeprom/Category entries, copied or taking the place of a
// generated category. See builder.hpp.

#include "esi/number.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/mapping.hpp"
#include "esi/sii/text.hpp"
#include "sii/builder.hpp"

namespace esi::sii::build_detail {

void Builder::build_copied_categories() {
    if (!device_.eeprom) return;
    for (const auto& cat : device_.eeprom->categories) {
        const SourcePos pos = cat.cat_no_pos.known() ? cat.cat_no_pos : cat.pos;
        if (cat.cat_no >= category::end) {
            diag(Severity::error, "sii-category-number",
                 fmt::format("Eeprom/Category CatNo {} is not a category number (0..0xFFFE)", cat.cat_no), pos);
            continue;
        }
        RawData raw;
        if (cat.data) {
            const auto bytes = cat.data->bytes();
            if (!bytes) {
                diag(Severity::error, "sii-category-data", "Eeprom/Category/Data is not valid hexBinary", cat.data->pos);
                continue;
            }
            raw.bytes = *bytes;
        } else if (cat.data_string) {
            const std::string s = to_sii_text(*cat.data_string);
            raw.bytes.assign(s.begin(), s.end());
        } else if (cat.data_uint) {
            const auto v = fit_unsigned(static_cast<std::int64_t>(*cat.data_uint), 16, "Eeprom/Category/DataUINT", cat.pos);
            raw.bytes = {static_cast<std::uint8_t>(v & 0xFF), static_cast<std::uint8_t>(v >> 8)};
        } else if (cat.data_udint) {
            const auto v = fit_unsigned(static_cast<std::int64_t>(*cat.data_udint), 32, "Eeprom/Category/DataUDINT", cat.pos);
            for (int i = 0; i < 4; ++i) raw.bytes.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF));
        } else {
            diag(Severity::warning, "sii-category-data", fmt::format("Eeprom/Category {} has no payload; it is written empty", cat.cat_no), cat.pos);
        }
        // The length word counts 16-bit words: a longer payload would be written with a
        // truncated length and break the category chain after it.
        if ((raw.bytes.size() + 1) / 2 > max_category_words) {
            diag(Severity::error, "sii-category-size",
                 fmt::format("Eeprom/Category {} has {} bytes of data; a category holds at most {} words ({} bytes), its "
                             "length word is 16 bits",
                             cat.cat_no, raw.bytes.size(), max_category_words, 2 * max_category_words),
                 cat.data ? cat.data->pos : pos);
            continue;
        }
        const auto type = static_cast<std::uint16_t>(cat.cat_no);
        if (!is_generated(type)) {
            image_.categories.push_back(Category{type, std::move(raw), 0, 0});
            continue;
        }
        // An explicit category of a type the builder writes itself wins (explicit declarations
        // win): it takes the generated one's place. It is decoded to report what a master
        // will trip over, since nothing else checks vendor-written bytes.
        if (explicit_.count(type)) {
            diag(Severity::warning, "sii-category-duplicate",
                 fmt::format("a second Eeprom/Category {} ({}); only the first is written", cat.cat_no, category_name(type)), pos);
            continue;
        }
        diag(type == category::strings ? Severity::warning : Severity::info, "sii-category-explicit",
             fmt::format("Eeprom/Category {} replaces the {} category the builder would write{}", cat.cat_no, category_name(type),
                         type == category::strings ? "; the string indices of the other categories then point into it" : ""),
             pos);
        std::vector<Fault> faults;
        CategoryContent content = decode_content(type, raw.bytes, 0, faults);
        for (const auto& f : faults)
            diag(Severity::warning, "sii-category-explicit",
                 fmt::format("Eeprom/Category {} ({}), payload byte {}: {}", cat.cat_no, category_name(type), f.offset, f.message), pos);
        // Keep the vendor's bytes exactly unless they decode cleanly.
        explicit_.emplace(type, Category{type, faults.empty() ? std::move(content) : CategoryContent{std::move(raw)}, 0, 0});
    }
}

bool Builder::is_generated(std::uint16_t type) {
    return type == category::strings || type == category::general || type == category::fmmu || type == category::sync_manager ||
           type == category::tx_pdo || type == category::rx_pdo || type == category::dc;
}

void Builder::add_category(std::uint16_t type, CategoryContent content) {
    if (const auto it = explicit_.find(type); it != explicit_.end()) {
        image_.categories.push_back(std::move(it->second));
        explicit_.erase(it);
        return;
    }
    image_.categories.push_back(Category{type, std::move(content), 0, 0});
}

General Builder::build_general() {
    General g;
    if (!omitted_.order_string) g.order_idx = add_string(device_.type.text, device_.type.pos, "Type");
    if (device_.group_type && !omitted_.group_string)
        g.group_idx = add_string(*device_.group_type, device_.group_type_pos, "GroupType");
    if (!omitted_.name_string) g.name_idx = add_string(localized(device_.names), device_.pos, "Device Name");
    g.group_idx_duplicate = g.group_idx;

    if (device_.mailbox) {
        const Mailbox& mb = *device_.mailbox;
        g.coe_details = coe_details_byte(mb);
        if (mb.foe) g.foe_details = 1;
        if (mb.eoe) g.eoe_details = 1;
        if (mb.soe)
            g.soe_channels = static_cast<std::uint8_t>(
                fit_unsigned(mb.soe->channel_count.value_or(1), 8, "SoE@ChannelCount", mb.soe->pos));
        if (mb.coe && mb.coe->ds402_channels)
            g.ds402_channels = static_cast<std::uint8_t>(fit_unsigned(*mb.coe->ds402_channels, 8, "CoE@DS402Channels", mb.coe->pos));
        if (mb.data_link_layer.value_or(false)) g.flags |= general_flag::mailbox_data_link_layer;
    }
    if (const XmlAttribute* a = device_.type.extras.attribute("UseLrdLwr"); a && parse_boolean(a->value).value_or(false))
        g.flags |= general_flag::enable_not_lrw;
    if (const XmlElement* e = device_.extras.find("Info/IdentificationReg134"); e && parse_boolean(e->text).value_or(false))
        g.flags |= general_flag::ident_al_status;
    if (const XmlElement* e = device_.extras.find("Info/IdentificationAdo")) {
        const ParsedNumber n = parse_number(e->text);
        if (n.ok() && !n.value.negative) {
            g.flags |= general_flag::ident_physical_memory;
            g.physical_memory_address = static_cast<std::uint16_t>(
                fit_unsigned(static_cast<std::int64_t>(n.value.magnitude & 0x7FFFFFFFFFFFFFFFull), 16, "Info/IdentificationAdo", e->pos));
        }
    }
    if (const XmlElement* e = device_.extras.find("Info/Electrical/EBusCurrent")) {
        if (const auto mA = ebus_current(device_))
            g.current_on_ebus = static_cast<std::int16_t>(fit_signed(*mA, 16, "Info/Electrical/EBusCurrent", e->pos));
        else
            diag(Severity::warning, "sii-ebus-current", fmt::format("Info/Electrical/EBusCurrent \"{}\" is not a number", e->text), e->pos);
    }

    // Physics: one letter per port, port 0 in the low nibble of bytes 16-17 (ETG.2010; the real
    // EK1100 image holds 0x0131 for Physics="YKY").
    if (device_.physics.size() > 4)
        diag(Severity::warning, "sii-physics",
             fmt::format("Physics \"{}\" names {} ports; the General category has room for 4", device_.physics,
                         device_.physics.size()),
             device_.pos);
    for (std::size_t i = 0; i < device_.physics.size() && i < 4; ++i) {
        const auto code = port_code(device_.physics[i]);
        if (!code)
            diag(Severity::warning, "sii-physics",
                 fmt::format("Physics letter '{}' (port {}) is not Y, H, K or space; the port is written as not used",
                             device_.physics[i], i),
                 device_.pos);
        g.physical_ports |= static_cast<std::uint16_t>(code.value_or(0) << (4 * i));
    }
    return g;
}

void Builder::build_fmmus() {
    if (device_.fmmus.empty()) return;
    Fmmus f;
    for (const auto& fmmu : device_.fmmus) {
        const auto code = fmmu_usage_code(fmmu.type);
        if (!code)
            diag(Severity::warning, "sii-fmmu-type",
                 fmt::format("Fmmu \"{}\" has no SII usage code; it is written as not used (0)", fmmu.type), fmmu.pos);
        f.usages.push_back(code.value_or(fmmu_usage::unused));
    }
    add_category(category::fmmu, std::move(f));
}

void Builder::build_sync_managers() {
    if (device_.sms.empty()) return;
    SyncManagers s;
    for (std::size_t i = 0; i < device_.sms.size(); ++i) {
        const SyncManager& sm = device_.sms[i];
        SyncManagerRecord r;
        r.start_address = static_cast<std::uint16_t>(fit_unsigned(sm.start_address.value_or(0), 16, fmt::format("Sm {} StartAddress", i), sm.pos));
        r.length = static_cast<std::uint16_t>(fit_unsigned(sm.default_size.value_or(0), 16, fmt::format("Sm {} DefaultSize", i), sm.pos));
        r.control = static_cast<std::uint8_t>(fit_unsigned(sm.control_byte.value_or(0), 8, fmt::format("Sm {} ControlByte", i), sm.pos));
        if (sm.enable && *sm.enable > 0xFF) fit_unsigned(*sm.enable, 8, fmt::format("Sm {} Enable", i), sm.pos);
        r.enable = sm_enable_byte(sm);
        const auto type = sm_type_code(sm.type);
        if (!type)
            diag(Severity::warning, "sii-sm-type",
                 fmt::format("Sm {} \"{}\" has no SII type code; it is written as unused (0)", i, sm.type), sm.pos);
        r.type = type.value_or(sm_type::unused);
        s.items.push_back(r);
    }
    add_category(category::sync_manager, std::move(s));
}

std::optional<DcOpModes> Builder::build_dc() {
    if (!options_.include_dc || omitted_.dc || !device_.dc) return std::nullopt;
    DcOpModes dc;
    std::size_t skipped = 0;
    for (const auto& op : device_.dc->op_modes) {
        if (is_legacy_op_mode(op)) {
            ++skipped;
            continue;
        }
        DcOpModeRecord r;
        const std::string label = fmt::format("Dc/OpMode \"{}\"", op.name);
        if (op.cycle_time_sync0) {
            r.cycle_time0 = static_cast<std::uint32_t>(fit_unsigned(op.cycle_time_sync0->value, 32, label + " CycleTimeSync0", op.cycle_time_sync0->pos));
            if (op.cycle_time_sync0->factor)
                r.sync0_cycle_factor = static_cast<std::int16_t>(fit_signed(*op.cycle_time_sync0->factor, 16, label + " CycleTimeSync0@Factor", op.cycle_time_sync0->pos));
        }
        if (op.shift_time_sync0) r.shift_time0 = fit_time(op.shift_time_sync0->value, label + " ShiftTimeSync0", op.shift_time_sync0->pos);
        if (op.shift_time_sync1) r.shift_time1 = fit_time(op.shift_time_sync1->value, label + " ShiftTimeSync1", op.shift_time_sync1->pos);
        if (op.cycle_time_sync1) {
            if (op.cycle_time_sync1->factor)
                r.sync1_cycle_factor = static_cast<std::int16_t>(fit_signed(*op.cycle_time_sync1->factor, 16, label + " CycleTimeSync1@Factor", op.cycle_time_sync1->pos));
            if (op.cycle_time_sync1->value != 0)
                diag(Severity::info, "sii-dc-cycle-time1",
                     fmt::format("{} CycleTimeSync1 is {} ns; the ETG.2010 DC category has no field for it (only its "
                                 "Factor), so it is not written",
                                 label, op.cycle_time_sync1->value),
                     op.cycle_time_sync1->pos);
        }
        r.assign_activate = static_cast<std::uint16_t>(fit_unsigned(op.assign_activate, 16, label + " AssignActivate", op.assign_activate_pos));
        r.name_idx = add_string(op.name, op.pos, "Dc/OpMode Name");
        if (op.desc && !omitted_.dc_descriptions) r.desc_idx = add_string(*op.desc, op.pos, "Dc/OpMode Desc");
        dc.items.push_back(r);
    }
    if (skipped > 0)
        diag(Severity::info, "sii-dc-legacy-op-mode",
             fmt::format("{} of {} Dc/OpMode elements are marked VendorSpecific/TwinCAT@IgnoreFromBuildNo (legacy modes) and "
                         "are not written, as in the vendor's own EEPROMs",
                         skipped, device_.dc->op_modes.size()),
             device_.dc->pos);
    if (dc.items.empty()) return std::nullopt;
    return dc;
}

Pdos Builder::build_pdos(const std::vector<Pdo>& pdos) {
    Pdos out;
    for (const auto& pdo : pdos) {
        if (omitted_.unassigned_pdos && !pdo.sm) continue;
        PdoRecord r;
        const std::string label = fmt::format("{} #x{:04X}", pdo.element_name(), pdo.index);
        r.index = static_cast<std::uint16_t>(fit_unsigned(pdo.index, 16, label + " Index", pdo.index_pos));
        if (pdo.sm) r.sync_manager = static_cast<std::uint8_t>(fit_unsigned(*pdo.sm, 8, label + " @Sm", pdo.pos));
        if (pdo.sm && *pdo.sm == pdo_no_sync_manager)
            diag(Severity::warning, "sii-value-range", label + " @Sm is 255, which SII reads as \"no SyncManager\"", pdo.pos);
        r.name_idx = add_string(localized(pdo.names), pdo.pos, label + " Name");
        r.flags = pdo_flags(pdo);
        if (pdo.entries.size() > 255)
            diag(Severity::error, "sii-pdo-entries",
                 fmt::format("{} has {} entries; the SII PDO header counts them in one byte (at most 255)", label, pdo.entries.size()),
                 pdo.pos);
        for (const auto& entry : pdo.entries) {
            PdoEntryRecord e;
            e.index = static_cast<std::uint16_t>(fit_unsigned(entry.index, 16, label + " Entry Index", entry.pos));
            e.subindex = static_cast<std::uint8_t>(fit_unsigned(entry.effective_subindex(), 8, label + " Entry SubIndex", entry.pos));
            e.bit_len = static_cast<std::uint8_t>(fit_unsigned(entry.bit_len, 8, fmt::format("{} Entry #x{:04X}:{:02X} BitLen", label, entry.index, entry.effective_subindex()), entry.bit_len_pos.known() ? entry.bit_len_pos : entry.pos));
            if (!entry.is_padding()) {
                e.name_idx = add_string(localized(entry.names), entry.pos, label + " Entry Name");
                if (const auto code = pdo_entry_data_type(device_, entry)) {
                    e.data_type = *code;
                } else {
                    diag(Severity::info, "sii-data-type",
                         fmt::format("{} entry #x{:04X}:{:02X}: data type \"{}\" has no one-byte CoE code; SII data type 0",
                                     label, entry.index, entry.effective_subindex(), entry.data_type.value_or("")),
                         entry.data_type_pos.known() ? entry.data_type_pos : entry.pos);
                }
            }
            r.entries.push_back(e);
        }
        out.items.push_back(std::move(r));
    }
    return out;
}

}  // namespace esi::sii::build_detail
