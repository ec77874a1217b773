// What a master configures for one slave, as one text: two ESI files that describe the same
// identity are interchangeable for a network exactly when their slaves' fingerprints are equal
// (network_build.cpp refuses a silent choice between two that are not). Names and comments
// are left out: they change no register, object or datagram.

#include <fmt/format.h>

#include "slave_context.hpp"

namespace esi::net {

std::string configuration_fingerprint(const NetworkSlave& s) {
    std::string out = fmt::format("id {:x} {:x} {:x} {} {}\n", s.vendor_id, s.product_code, s.revision, static_cast<int>(s.revision_check),
                                  s.identification_reg134);
    for (const SmSetup& sm : s.sms)
        out += fmt::format("sm {} {} {:x} {} {:x} {} {} {} {} {} {}\n", sm.number, static_cast<int>(sm.kind), sm.start_address, sm.length,
                           sm.control_byte, sm.enable, sm.op_only, sm.is_virtual, sm.min_size.value_or(~0u), sm.max_size.value_or(~0u),
                           sm.default_size.value_or(~0u));
    for (const FmmuSetup& f : s.fmmus)
        out += fmt::format("fmmu {} {} {} {} {:x} {} {}\n", f.number, static_cast<int>(f.kind), f.sm, f.length, f.physical_start,
                           f.logical_stop_bit, f.enable);
    for (const ConfiguredPdo& p : s.pdos) {
        out += fmt::format("pdo {} {:x} {} {}\n", static_cast<int>(p.direction), p.index, p.sm, p.fixed);
        for (const ConfiguredEntry& e : p.entries) out += fmt::format(" entry {:x} {:x} {} {}\n", e.index, e.subindex, e.bit_len, e.data_type);
    }
    if (s.mailbox) {
        const MailboxSetup& m = *s.mailbox;
        out += fmt::format("mailbox {:x} {} {:x} {} {}{}{}{}{}{} {}{}{}\n", m.out_start, m.out_length, m.in_start, m.in_length, m.coe, m.eoe,
                           m.foe, m.soe, m.aoe, m.voe, m.complete_access, m.pdo_assign, m.pdo_config);
        for (const auto& [profile, info] : m.channel_info) out += fmt::format(" channel {} {}\n", profile, info);
    }
    for (const CoeCommand& c : s.coe_init_cmds) {
        out += fmt::format("coe {:x} {:x} {} ", c.index, c.subindex, c.complete_access);
        for (const std::string& t : c.transitions) out += t + ",";
        for (std::uint8_t b : c.data) out += fmt::format("{:02x}", b);
        out += '\n';
    }
    if (s.dc) out += fmt::format("dc {:x} {} {} {}\n", s.dc->assign_activate, s.dc->cycle_time0, s.dc->cycle_time1, s.dc->shift_time0);
    out += fmt::format("timeouts {} {} {} {}\n", s.timeouts.preop, s.timeouts.safeop_op, s.timeouts.back_to_init, s.timeouts.back_to_safeop);
    out += fmt::format("watchdog {} {} {}\n", s.watchdog_divider.value_or(0), s.pdi_watchdog.value_or(0), s.sm_watchdog.value_or(0));
    return out;
}

}  // namespace esi::net
