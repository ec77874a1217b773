// One datagram as one ESC executes it (ETG.1000.4 §5.4 "EtherCAT commands"): addressing, the
// data it reads into or writes from the frame, and the working counter.

#include <vector>

#include "esi/esc/esc.hpp"
#include "esi/ethercat/registers.hpp"

namespace esi::esc {

namespace reg = ethercat::reg;

void Esc::begin_pass(const FramePass& pass) {
    pass_ = pass;
    watchdog_check();
    refresh_system_time();
    refresh_dl_status();
    // Idealised SYNC: one SYNC0 (and SYNC1) event per frame while the unit is active.
    const std::uint8_t active = memory_[reg::dc_activation_status];
    if (active & 1) {
        memory_[reg::dc_sync0_status] |= 1;
        set_al_event(reg::al_event_sync0);
    }
    if (active & 2) {
        memory_[reg::dc_sync1_status] |= 1;
        set_al_event(reg::al_event_sync1);
    }
}

bool Esc::station_matches(std::uint16_t adp) const {
    if (adp == peek16(reg::station_address)) return true;
    return (memory_[reg::dl_alias] & 1) && adp == peek16(reg::station_alias);
}

// Physical access at ADO: reads replace the frame's bytes (broadcast reads OR them in, so the
// master sees the union over all slaves); writes take the bytes as they arrived. A refused part
// (mailbox full or empty) leaves the frame and memory as they were and does not count.
void Esc::physical(Datagram& d, bool addressed, bool reads, bool writes, bool or_reads) {
    if (!addressed || d.data.empty()) return;
    std::vector<std::uint8_t> sent;
    if (writes && reads) sent.assign(d.data.begin(), d.data.end());
    if (reads) {
        std::vector<std::uint8_t> value(d.data.size());
        if (access(Side::ecat, false, d.ado, value)) {
            for (std::size_t i = 0; i < value.size(); ++i) d.data[i] = or_reads ? (d.data[i] | value[i]) : value[i];
            d.working_counter = static_cast<std::uint16_t>(d.working_counter + 1);
        }
    }
    if (writes) {
        std::span<std::uint8_t> source = reads ? std::span<std::uint8_t>(sent) : d.data;
        if (access(Side::ecat, true, d.ado, source))
            d.working_counter = static_cast<std::uint16_t>(d.working_counter + (reads ? 2 : 1));
    }
}

void Esc::process(Datagram& d) {
    switch (static_cast<Command>(d.command)) {
    case Command::aprd: physical(d, d.adp == 0, true, false, false); ++d.adp; break;
    case Command::apwr: physical(d, d.adp == 0, false, true, false); ++d.adp; break;
    case Command::aprw: physical(d, d.adp == 0, true, true, false); ++d.adp; break;
    case Command::fprd: physical(d, station_matches(d.adp), true, false, false); break;
    case Command::fpwr: physical(d, station_matches(d.adp), false, true, false); break;
    case Command::fprw: physical(d, station_matches(d.adp), true, true, false); break;
    case Command::brd: physical(d, true, true, false, true); ++d.adp; break;
    case Command::bwr: physical(d, true, false, true, false); ++d.adp; break;
    case Command::brw: physical(d, true, true, true, true); ++d.adp; break;
    case Command::lrd: case Command::lwr: case Command::lrw: process_logical(d); break;
    // Read multiple write: the addressed slave reads, every other slave writes what it read
    // (the master distributes the reference clock's system time this way).
    case Command::armw: physical(d, true, d.adp == 0, d.adp != 0, false); ++d.adp; break;
    case Command::frmw: {
        const bool addressed = station_matches(d.adp);
        physical(d, true, addressed, !addressed, false);
        break;
    }
    case Command::nop:
    default: break;  // unknown commands pass unchanged
    }
    d.irq = static_cast<std::uint16_t>(d.irq | (peek16(reg::ecat_event_request) & peek16(reg::ecat_event_mask)));
}

}  // namespace esi::esc
