// SyncManagers, FMMUs and the mailbox of one slave, from its ESI and its PDO assignment, the
// way TwinCAT configures them (corpus ENI exports; register layouts: Beckhoff ESC datasheet
// section II, SyncManager 0x0800 + 8n, FMMU 0x0600 + 16n):
//  - mailbox SMs take their ESI DefaultSize and are enabled;
//  - a process-data SM is as long as its assigned PDOs (bits rounded up to bytes) and enabled
//    when that is not zero; an SM without any assigned PDO is written with control byte 0;
//  - each Outputs/Inputs FMMU of the ESI serves the next process-data SM of its direction (or
//    the SM its Sm attribute names); an MBoxState FMMU maps SM1's status byte (0x080D) to the
//    master's mailbox-state area, one bit per slave.

#include <fmt/format.h>

#include "esi/number.hpp"
#include "slave_context.hpp"
#include "sm_kind.hpp"

namespace esi::net {

namespace {

std::optional<std::uint32_t> extras_number(const Extras& extras, std::string_view path) {
    const XmlElement* e = extras.find(path);
    if (!e) return std::nullopt;
    const ParsedNumber n = parse_number(e->text);
    if (!n.ok() || n.value.negative || n.value.magnitude > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<std::uint32_t>(n.value.magnitude);
}

std::uint16_t le16(const std::vector<std::uint8_t>& b, std::size_t at) {
    return static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
}

}  // namespace

void setup_sync_managers(SlaveContext& c) {
    NetworkSlave& s = c.slave;
    const Device& d = c.device;

    for (std::size_t i = 0; i < d.sms.size(); ++i) {
        const SyncManager& esi_sm = d.sms[i];
        SmSetup sm;
        sm.number = static_cast<std::uint32_t>(i);
        sm.kind = sm_kind_of(esi_sm.type);
        sm.type = esi_sm.type;
        sm.start_address = static_cast<std::uint16_t>(esi_sm.start_address.value_or(0));
        sm.control_byte = static_cast<std::uint8_t>(esi_sm.control_byte.value_or(0));
        sm.op_only = esi_sm.op_only.value_or(false);
        sm.is_virtual = esi_sm.is_virtual.value_or(false);
        sm.min_size = esi_sm.min_size;
        sm.max_size = esi_sm.max_size;
        sm.default_size = esi_sm.default_size;
        if (!esi_sm.start_address && sm.kind != SmKind::unused)
            c.error(c.spec.device_pos, "net-sm", fmt::format("SM{} of {} has no StartAddress in the ESI", i, d.type.text));
        if (sm.kind == SmKind::mailbox_out || sm.kind == SmKind::mailbox_in) {
            sm.length = static_cast<std::uint16_t>(esi_sm.default_size.value_or(esi_sm.max_size.value_or(esi_sm.min_size.value_or(0))));
            sm.enable = true;
        } else if (sm.is_process_data()) {
            std::uint32_t bits = 0;
            for (std::size_t p = 0; p < s.pdos.size(); ++p)
                if (s.pdos[p].sm == sm.number) {
                    sm.pdos.push_back(p);
                    bits += s.pdos[p].bit_size();
                }
            const std::uint32_t bytes = (bits + 7) / 8;
            if (sm.max_size && bytes > *sm.max_size)
                c.error(c.spec.pdos ? c.spec.pdos_pos : c.spec.pos, "net-sm-size",
                        fmt::format("the PDOs assigned to SM{} take {} bytes; the ESI allows at most {} (MaxSize)", i, bytes, *sm.max_size));
            if (bytes > 0xFFFF) c.error(c.spec.pos, "net-sm-size", fmt::format("SM{}: {} bytes of process data", i, bytes));
            sm.length = static_cast<std::uint16_t>(std::min<std::uint32_t>(bytes, 0xFFFF));
            sm.enable = sm.length > 0;
            if (sm.pdos.empty()) sm.control_byte = 0;
            (sm.kind == SmKind::outputs ? s.output_bytes : s.input_bytes) += sm.length;
        }
        s.sms.push_back(std::move(sm));
    }

    // FMMUs, in ESI order.
    std::vector<bool> served(s.sms.size(), false);
    auto next_sm = [&](SmKind kind) -> std::optional<std::uint32_t> {
        for (const SmSetup& sm : s.sms)
            if (sm.kind == kind && !served[sm.number]) return sm.number;
        return std::nullopt;
    };
    for (std::size_t i = 0; i < d.fmmus.size(); ++i) {
        const Fmmu& f = d.fmmus[i];
        FmmuSetup fmmu;
        fmmu.number = static_cast<std::uint32_t>(i);
        if (f.type == "Outputs" || f.type == "Inputs") {
            fmmu.kind = f.type == "Outputs" ? FmmuKind::outputs : FmmuKind::inputs;
            const SmKind kind = f.type == "Outputs" ? SmKind::outputs : SmKind::inputs;
            std::optional<std::uint32_t> sm = f.sm;
            if (sm && (*sm >= s.sms.size() || s.sms[*sm].kind != kind)) sm.reset();
            if (!sm) sm = next_sm(kind);
            if (sm) {
                served[*sm] = true;
                fmmu.sm = *sm;
                fmmu.physical_start = s.sms[*sm].start_address;
                fmmu.length = s.sms[*sm].length;
                fmmu.enable = fmmu.length > 0;
            } else {
                fmmu.enable = false;
            }
            if (!fmmu.enable) fmmu.logical_stop_bit = 0;
        } else if (f.type == "MBoxState") {
            fmmu.kind = FmmuKind::mailbox_state;
            fmmu.sm = 1;
            fmmu.length = 1;
            fmmu.physical_start = 0x080D;  // SM1 status byte
            fmmu.logical_stop_bit = 0;
        } else {
            continue;  // DynamicInputs/DynamicOutputs: not configured by a master from the ESI
        }
        s.fmmus.push_back(fmmu);
    }
    for (const SmSetup& sm : s.sms)
        if (sm.is_process_data() && sm.length > 0 && !served[sm.number])
            c.error(c.spec.pos, "net-fmmu",
                    fmt::format("{} has no {} FMMU left for SM{} (ESI Fmmu elements)", d.type.text,
                                sm.kind == SmKind::outputs ? "Outputs" : "Inputs", sm.number));

    // Mailbox.
    if (d.mailbox) {
        MailboxSetup m;
        for (const SmSetup& sm : s.sms) {
            if (sm.kind == SmKind::mailbox_out) {
                m.out_start = sm.start_address;
                m.out_length = sm.length;
            } else if (sm.kind == SmKind::mailbox_in) {
                m.in_start = sm.start_address;
                m.in_length = sm.length;
            }
        }
        if (d.eeprom && d.eeprom->boot_strap)
            if (const auto b = d.eeprom->boot_strap->bytes(); b && b->size() == 8) {
                m.boot_out_start = le16(*b, 0);
                m.boot_out_length = le16(*b, 2);
                m.boot_in_start = le16(*b, 4);
                m.boot_in_length = le16(*b, 6);
            }
        m.coe = d.mailbox->coe.has_value();
        m.eoe = d.mailbox->eoe.has_value();
        m.foe = d.mailbox->foe.has_value();
        m.soe = d.mailbox->soe.has_value();
        m.aoe = d.mailbox->aoe.has_value();
        m.voe = d.mailbox->voe.has_value();
        m.data_link_layer = d.mailbox->data_link_layer;
        if (d.mailbox->coe) {
            m.complete_access = d.mailbox->coe->complete_access.value_or(false);
            m.pdo_assign = d.mailbox->coe->pdo_assign.value_or(false);
            m.pdo_config = d.mailbox->coe->pdo_config.value_or(false);
        }
        for (const Profile& p : d.profiles) {
            const std::uint32_t channels = std::min<std::uint32_t>(extras_number(p.extras, "ChannelCount").value_or(1), 64);
            for (std::uint32_t ch = 0; p.profile_no && ch < channels; ++ch) m.channel_info.emplace_back(*p.profile_no, p.add_info.value_or(0));
        }
        for (const ModuleInSlot& mod : s.modules)
            if (mod.module->profile && mod.module->profile->profile_no)
                m.channel_info.emplace_back(*mod.module->profile->profile_no, mod.module->profile->add_info.value_or(0));
        if (c.limits.max_mailbox_size && (m.out_length > *c.limits.max_mailbox_size || m.in_length > *c.limits.max_mailbox_size))
            c.error(c.spec.pos, "net-limit-mailbox",
                    fmt::format("mailbox of {} / {} bytes; the device takes at most {} (limits)", m.out_length, m.in_length, *c.limits.max_mailbox_size));
        s.mailbox = std::move(m);
    }

    // ESI Info/StateMachine/Timeout, ESC watchdog registers, identity checks.
    if (auto v = extras_number(d.extras, "Info/StateMachine/Timeout/PreopTimeout")) s.timeouts.preop = *v;
    if (auto v = extras_number(d.extras, "Info/StateMachine/Timeout/SafeopOpTimeout")) s.timeouts.safeop_op = *v;
    if (auto v = extras_number(d.extras, "Info/StateMachine/Timeout/BackToInitTimeout")) s.timeouts.back_to_init = *v;
    if (auto v = extras_number(d.extras, "Info/StateMachine/Timeout/BackToSafeopTimeout")) s.timeouts.back_to_safeop = *v;
    auto reg16 = [&](std::string_view path) -> std::optional<std::uint16_t> {
        if (auto v = extras_number(d.extras, path); v && *v <= 0xFFFF) return static_cast<std::uint16_t>(*v);
        return std::nullopt;
    };
    s.watchdog_divider = reg16("ESC/Reg0400");
    s.pdi_watchdog = reg16("ESC/Reg0410");
    s.sm_watchdog = reg16("ESC/Reg0420");
    if (const XmlAttribute* check = d.type.extras.attribute("CheckRevisionNo")) {
        if (check->value == "EQ") s.revision_check = RevisionCheck::full;
        else if (check->value == "LW_EQ") s.revision_check = RevisionCheck::low_word;
    }
    if (const XmlElement* e = d.extras.find("Info/IdentificationReg134"))
        s.identification_reg134 = parse_boolean(e->text).value_or(false);
}

}  // namespace esi::net
