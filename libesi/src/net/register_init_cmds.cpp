// The register init commands, in the order of the corpus exports (TwinCAT: MEGA, KP, CHERRY;
// EC-Engineer: ROCOS). Register addresses: Beckhoff ESC datasheet section II — 0x0010 station
// address, 0x0120 AL control, 0x0130 AL status (+ 0x0134 status code), 0x0400/0x0410/0x0420
// watchdogs, 0x0500 SII access, 0x0502 SII control/address, 0x0508 SII data, 0x0600 FMMUs,
// 0x0800 SyncManagers, 0x0980 DC activation, 0x0990 SYNC0 start time, 0x09A0 SYNC0/1 cycle
// times, 0x09A8 latch configuration.
//
// Before the station address is set (and whenever it may be lost: requests for INIT, the SII
// back to ECAT) a slave is addressed by position (APRD/APWR); afterwards by its station
// address (FPRD/FPWR). Commands of up-transitions expect a working counter of 1 (Cnt); clears
// and down-transitions expect none, since the slave may be gone. The AL status check reads
// 6 bytes (status and status code) and masks 0x1F going up (state and error bit) and 0x0F
// going down or to INIT.

#include "register_init_cmds.hpp"

#include "esi/ethercat/registers.hpp"

namespace esi::net {

namespace reg = ethercat::reg;

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes le16(std::uint32_t v) { return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8)}; }
Bytes le32(std::uint32_t v) {
    return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v >> 16),
            static_cast<std::uint8_t>(v >> 24)};
}
Bytes zeros(std::size_t n) { return Bytes(n, 0); }

// AL control/status state codes (ETG.1000.6): INIT 1, PREOP 2, BOOT 3, SAFEOP 4, OP 8.
Bytes state_request(std::uint8_t state, bool acknowledge) {
    return {static_cast<std::uint8_t>(state | (acknowledge ? 0x10 : 0)), 0};
}
Bytes status6(std::uint8_t state) { return {state, 0, 0, 0, 0, 0}; }

struct Builder {
    const NetworkSlave& s;
    std::vector<RegisterCommand> out;

    RegisterCommand& add(std::vector<std::string> transitions, std::string comment, RegisterCmd cmd, std::uint16_t ado, Bytes data) {
        RegisterCommand c;
        c.transitions = std::move(transitions);
        c.comment = std::move(comment);
        c.cmd = cmd;
        c.adp = cmd == RegisterCmd::aprd || cmd == RegisterCmd::apwr ? s.auto_inc_addr : s.phys_addr;
        c.ado = ado;
        c.data = std::move(data);
        out.push_back(std::move(c));
        return out.back();
    }
    RegisterCommand& up(std::vector<std::string> transitions, std::string comment, RegisterCmd cmd, std::uint16_t ado, Bytes data) {
        RegisterCommand& c = add(std::move(transitions), std::move(comment), cmd, ado, std::move(data));
        c.cnt = 1;
        return c;
    }
    void check(RegisterCommand& c, Bytes expected, std::optional<Bytes> mask, std::uint32_t timeout) {
        c.validate = RegisterValidate{std::move(expected), std::move(mask), timeout};
    }
};

std::string sm_label(const SmSetup& sm) {
    switch (sm.kind) {
        case SmKind::mailbox_out: return "mailbox out";
        case SmKind::mailbox_in: return "mailbox in";
        case SmKind::outputs: return "outputs";
        case SmKind::inputs: return "inputs";
        default: return "unused";
    }
}

std::string fmmu_label(const FmmuSetup& f) {
    switch (f.kind) {
        case FmmuKind::outputs: return "outputs";
        case FmmuKind::inputs: return "inputs";
        default: return "mailbox state";
    }
}

}  // namespace

std::vector<std::uint8_t> sm_register_data(std::uint16_t start, std::uint16_t length, std::uint8_t control, bool enable) {
    Bytes d = le16(start);
    const Bytes l = le16(length);
    d.insert(d.end(), l.begin(), l.end());
    d.push_back(control);
    d.push_back(0);  // status (read only)
    d.push_back(enable ? 1 : 0);
    d.push_back(0);  // PDI control
    return d;
}

std::vector<std::uint8_t> fmmu_register_data(const FmmuSetup& f) {
    if (!f.enable && f.kind != FmmuKind::mailbox_state) {
        Bytes d = zeros(16);
        d[11] = f.type();
        return d;
    }
    Bytes d = le32(f.logical_start);
    const Bytes l = le16(f.length);
    d.insert(d.end(), l.begin(), l.end());
    d.push_back(f.logical_start_bit);
    d.push_back(f.logical_stop_bit);
    const Bytes p = le16(f.physical_start);
    d.insert(d.end(), p.begin(), p.end());
    d.push_back(f.physical_start_bit);
    d.push_back(f.type());
    d.push_back(f.enable ? 1 : 0);
    d.push_back(0);
    d.push_back(0);
    d.push_back(0);
    return d;
}

std::vector<RegisterCommand> master_init_cmds() {
    std::vector<RegisterCommand> out;
    auto add = [&](std::vector<std::string> transitions, std::string comment, RegisterCmd cmd, std::uint16_t ado, Bytes data,
                   std::uint16_t retries = 3) -> RegisterCommand& {
        RegisterCommand c;
        c.transitions = std::move(transitions);
        c.before_slave = true;
        c.comment = std::move(comment);
        c.cmd = cmd;
        c.ado = ado;
        c.data = std::move(data);
        c.retries = retries;
        out.push_back(std::move(c));
        return out.back();
    };
    add({"IP"}, "read slave count", RegisterCmd::brd, reg::al_status, zeros(2), 0);
    add({"IP"}, "read slave count", RegisterCmd::brd, reg::al_status, zeros(2), 0);
    add({"IP"}, "enable ECAT IRQ", RegisterCmd::bwr, reg::ecat_event_mask, {0x04, 0x00});
    add({"IP"}, "clear configured addresses", RegisterCmd::bwr, reg::station_address, zeros(2));
    add({"IP"}, "clear crc register", RegisterCmd::bwr, reg::error_counters, zeros(8));
    add({"IP", "PI", "BI", "SI", "OI"}, "clear fmmu", RegisterCmd::bwr, reg::fmmu0, {}).data_length = 256;
    add({"IP"}, "clear sm", RegisterCmd::bwr, reg::sm0, {}).data_length = 256;
    add({"IP"}, "clear dc system time", RegisterCmd::bwr, reg::dc_system_time, {}).data_length = 32;
    add({"IP"}, "clear dc cycle cfg", RegisterCmd::bwr, reg::dc_sync_activation, zeros(1));
    add({"IP"}, "reset dc speed", RegisterCmd::bwr, reg::dc_speed_counter_start, {0x00, 0x10});
    add({"IP"}, "configure dc filter", RegisterCmd::bwr, reg::dc_time_filter, {0x00, 0x0C});
    add({"IP"}, "en/disable second physical address", RegisterCmd::bwr, reg::dl_alias, zeros(1));
    return out;
}

std::vector<RegisterCommand> slave_init_cmds(const Network& network, const NetworkSlave& s) {
    (void)network;
    Builder b{s, {}};
    const StateTimeouts& t = s.timeouts;
    const bool mailbox = s.mailbox.has_value();
    const Bytes mask_init = {0x0F, 0x00};
    const Bytes mask_down = {0x0F, 0, 0, 0, 0, 0};
    const Bytes mask_up = {0x1F, 0, 0, 0, 0, 0};
    using enum RegisterCmd;

    b.add({"PI", "BI", "SI", "OI"}, "set device state to INIT", apwr, reg::al_control, state_request(1, mailbox)).timeout_ms = t.back_to_init;
    if (s.dc) b.add({"SI", "OI"}, "clear DC activation", apwr, reg::dc_cyclic_unit_control, zeros(2));
    b.check(b.add({"PI", "SI", "OI"}, "check device state for INIT", aprd, reg::al_status, zeros(2)), {0x01, 0x00}, mask_init, t.back_to_init);
    b.check(b.add({"BI"}, "check device state for INIT", aprd, reg::al_status, zeros(2)), {0x01, 0x00}, mask_init, 10000);
    b.up({"IP", "IB"}, "set device state to INIT", apwr, reg::al_control, state_request(1, mailbox)).timeout_ms = t.preop;
    b.check(b.up({"IP", "IB"}, "check device state for INIT", aprd, reg::al_status, zeros(2)), {0x01, 0x00}, mask_init, t.preop);

    // Identity, read from the SII (word 8 vendor, 0x0A product code, 0x0C revision).
    b.up({"IP"}, "assign EEPROM to ECAT", apwr, reg::eeprom_configuration, zeros(1));
    auto sii_check = [&](const std::string& comment, std::uint8_t word, Bytes expected) {
        b.up({"IP"}, comment, apwr, reg::eeprom_control, {0x00, 0x01, word, 0x00, 0x00, 0x00}).requires_cycle = false;
        const std::size_t size = expected.size();
        b.check(b.up({"IP"}, comment, aprd, reg::eeprom_data, zeros(size)), std::move(expected), std::nullopt, 100);
    };
    sii_check("check vendor id", 0x08, le32(s.vendor_id));
    sii_check("check product code", 0x0A, le32(s.product_code));
    if (s.revision_check == RevisionCheck::full) sii_check("check revision number", 0x0C, le32(s.revision));
    if (s.revision_check == RevisionCheck::low_word) sii_check("check revision number (lo word)", 0x0C, le16(s.revision & 0xFFFF));
    b.up({"IP", "IB"}, "set physical address", apwr, reg::station_address, le16(s.phys_addr));

    if (s.watchdog_divider) b.up({"IP"}, "set watchdog divider", fpwr, reg::watchdog_divider, le16(*s.watchdog_divider)).requires_cycle = false;
    if (s.pdi_watchdog) b.up({"IP"}, "set PDI watchdog", fpwr, reg::watchdog_time_pdi, le16(*s.pdi_watchdog)).requires_cycle = false;
    if (s.sm_watchdog) b.up({"IP"}, "set SM watchdog", fpwr, reg::watchdog_time_process_data, le16(*s.sm_watchdog)).requires_cycle = false;

    // Mailbox SyncManagers (SM0/SM1), and the bootstrap mailbox when the ESI gives one.
    const SmSetup* mbx_out = nullptr;
    const SmSetup* mbx_in = nullptr;
    for (const SmSetup& sm : s.sms) {
        if (sm.kind == SmKind::mailbox_out && !mbx_out) mbx_out = &sm;
        if (sm.kind == SmKind::mailbox_in && !mbx_in) mbx_in = &sm;
    }
    if (mbx_out && mbx_in) {
        const bool boot = s.mailbox && s.mailbox->boot_out_start && s.mailbox->boot_in_start;
        b.add({"IP", "IB", "PI", "SI", "OI"}, "clear sm 0/1 (mailbox out/in)", fpwr, reg::sm0, zeros(16)).requires_cycle = false;
        b.add({"BI"}, "clear sm 0/1 (mailbox out/in)", apwr, reg::sm0, zeros(16)).requires_cycle = false;
        const std::vector<std::string> when = boot ? std::vector<std::string>{"IP"} : std::vector<std::string>{"IP", "IB"};
        for (const SmSetup* sm : {mbx_out, mbx_in})
            b.up(when, "set sm " + std::to_string(sm->number) + " (" + sm_label(*sm) + ")", fpwr,
                 reg::sm(sm->number), sm_register_data(sm->start_address, sm->length, sm->control_byte, true))
                .requires_cycle = false;
        if (boot) {
            const MailboxSetup& m = *s.mailbox;
            b.up({"IB"}, "set sm " + std::to_string(mbx_out->number) + " (bootstrap out)", fpwr, reg::sm(mbx_out->number),
                 sm_register_data(*m.boot_out_start, *m.boot_out_length, mbx_out->control_byte, true))
                .requires_cycle = false;
            b.up({"IB"}, "set sm " + std::to_string(mbx_in->number) + " (bootstrap in)", fpwr, reg::sm(mbx_in->number),
                 sm_register_data(*m.boot_in_start, *m.boot_in_length, mbx_in->control_byte, true))
                .requires_cycle = false;
        }
    }

    if (s.dc) {
        Bytes cycle = le32(s.dc->cycle_time0);
        const Bytes cycle1 = le32(s.dc->cycle_time1);
        cycle.insert(cycle.end(), cycle1.begin(), cycle1.end());
        b.up({"PS"}, "set DC cycle time", fpwr, reg::dc_sync0_cycle, cycle);
        // The start time is a placeholder: the master writes its own, a few cycles ahead.
        b.up({"PS"}, "set DC start time", fpwr, reg::dc_start_time, zeros(8));
        b.up({"PS"}, "set DC activation", fpwr, reg::dc_cyclic_unit_control, le16(s.dc->assign_activate));
        b.add({"PS"}, "set DC latch cfg", fpwr, reg::dc_latch0_control, zeros(2));
        b.add({"IP", "PP"}, "clear DC activation", fpwr, reg::dc_cyclic_unit_control, zeros(2));
    }

    RegisterCommand& preop = b.add({"SP", "OP"}, "set device state to PREOP", fpwr, reg::al_control, state_request(2, mailbox));
    preop.retries = 300;
    preop.timeout_ms = t.back_to_safeop;

    // Process-data SyncManagers and FMMUs.
    // Virtual SMs (ESI Sm@Virtual) are no SyncManagers: only their FMMUs are written.
    std::vector<const SmSetup*> pd;
    for (const SmSetup& sm : s.sms)
        if (sm.is_process_data() && !sm.is_virtual) pd.push_back(&sm);
    if (!pd.empty()) {
        const std::uint32_t first = pd.front()->number, last = pd.back()->number;
        b.add({"IP", "SP", "SI", "OP", "OI"}, "clear sms", fpwr, reg::sm(first), zeros(8 * (last - first + 1)))
            .requires_cycle = false;
        for (const SmSetup* sm : pd)
            if (sm->op_only)
                b.add({"OS"}, std::string("clear ") + (sm->kind == SmKind::outputs ? "output" : "input") + " sm", fpwr,
                      reg::sm(sm->number), zeros(8))
                    .requires_cycle = false;
        for (const SmSetup* sm : pd)
            b.up({sm->op_only ? "SO" : "PS"}, "set sm " + std::to_string(sm->number) + " (" + sm_label(*sm) + ")", fpwr,
                 reg::sm(sm->number), sm_register_data(sm->start_address, sm->length, sm->control_byte, sm->enable))
                .requires_cycle = false;
    }
    for (const FmmuSetup& f : s.fmmus) {
        const bool state = f.kind == FmmuKind::mailbox_state;
        b.up(state ? std::vector<std::string>{"IP", "IB"} : std::vector<std::string>{"PS"},
             "set fmmu " + std::to_string(f.number) + " (" + fmmu_label(f) + ")", fpwr, reg::fmmu(f.number),
             fmmu_register_data(f))
            .requires_cycle = false;
    }
    b.add({"OS"}, "set device state to SAFEOP", fpwr, reg::al_control, state_request(4, false)).timeout_ms = t.back_to_safeop;
    for (const FmmuSetup& f : s.fmmus) {
        const bool state = f.kind == FmmuKind::mailbox_state;
        b.add(state ? std::vector<std::string>{"PI", "BI", "SI", "OI"} : std::vector<std::string>{"SP", "SI", "OP", "OI"},
              "clear fmmu " + std::to_string(f.number), fpwr, reg::fmmu(f.number), zeros(16))
            .requires_cycle = false;
    }
    if (s.dc) b.add({"SP", "OP"}, "clear DC activation", fpwr, reg::dc_cyclic_unit_control, zeros(2));
    b.check(b.add({"SP", "OP"}, "check device state for PREOP", fprd, reg::al_status, zeros(6)), status6(2), mask_down, t.back_to_init);

    b.up({"IP", "IB"}, "assign EEPROM to PDI", fpwr, reg::eeprom_configuration, {0x01});
    b.add({"II"}, "assign EEPROM back to ECAT", apwr, reg::eeprom_configuration, zeros(1));
    RegisterCommand& to_preop = b.up({"IP"}, "set device state to PREOP", fpwr, reg::al_control, state_request(2, mailbox));
    to_preop.retries = 300;
    to_preop.timeout_ms = t.preop;
    b.check(b.up({"IP"}, "check device state for PREOP", fprd, reg::al_status, zeros(6)), status6(2), mask_up, t.preop);
    b.add({"IP", "BI"}, "assign EEPROM back to ECAT", apwr, reg::eeprom_configuration, zeros(1));
    b.up({"IB"}, "set device state to BOOT", fpwr, reg::al_control, state_request(3, mailbox)).timeout_ms = t.preop;
    b.check(b.up({"IB"}, "check device state for BOOT", fprd, reg::al_status, zeros(6)), status6(3), mask_up, t.preop);
    b.up({"PS"}, "set device state to SAFEOP", fpwr, reg::al_control, state_request(4, false)).timeout_ms = t.safeop_op;
    b.check(b.up({"PS"}, "check device state for SAFEOP", fprd, reg::al_status, zeros(6)), status6(4), mask_up, t.safeop_op);
    b.check(b.add({"OS"}, "check device state for SAFEOP", fprd, reg::al_status, zeros(6)), status6(4), mask_down, t.back_to_safeop);
    b.up({"SO"}, "set device state to OP", fpwr, reg::al_control, state_request(8, false)).timeout_ms = t.safeop_op;
    b.check(b.up({"SO"}, "check device state for OP", fprd, reg::al_status, zeros(6)), status6(8), mask_up, t.safeop_op);
    return std::move(b.out);
}

}  // namespace esi::net
