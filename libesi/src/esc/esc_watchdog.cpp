// The process-data watchdog (ESC datasheet section II, 0x0400 divider, 0x0420 time, 0x0440
// status, 0x0442 counter; SyncManager control bit 6): every write by the master into the buffer
// of an enabled SyncManager whose control byte has the watchdog trigger bit rewinds it; when it
// runs out, 0x0440 bit 0 goes to 0, the expiry counter counts and the AL event request bit 6
// tells the PDI, which then puts the outputs in their safe state. The next trigger sets the
// status back to 1.
//
// Time is the frame's: the ESC sees time pass only when a frame arrives, so the watchdog is
// looked at when each frame begins to pass (begin_pass), before its datagrams can trigger it.
// A master that stops sending learns of the expiry with its next frame, and the firmware,
// polled after that frame, reacts to it then — as a real device would have done at expiry.

#include "esi/esc/esc.hpp"

#include "esi/ethercat/registers.hpp"

namespace esi::esc {

namespace reg = ethercat::reg;

namespace {

// One watchdog tick: (divider + 2) periods of the 25 MHz clock, 40 ns each.
constexpr std::uint64_t clock_period_ns = 40;

}  // namespace

void Esc::watchdog_triggered_by(std::uint32_t sm_hits) {
    for (unsigned n = 0; n < config_.sync_managers; ++n) {
        if (!(sm_hits & (1u << n))) continue;
        if (!(memory_[reg::sm0 + reg::sm_stride * n + reg::sm_control] & reg::sm_control_watchdog_trigger)) continue;
        watchdog_armed_ = true;
        watchdog_trigger_ns_ = pass_.port0_time_ns;
        memory_[reg::watchdog_status_process_data] |= 0x01;
        return;
    }
}

void Esc::watchdog_check() {
    const std::uint16_t ticks = peek16(reg::watchdog_time_process_data);
    if (ticks == 0) {  // disabled: the status reads "active or disabled"
        memory_[reg::watchdog_status_process_data] |= 0x01;
        return;
    }
    if (!watchdog_armed_ || !(memory_[reg::watchdog_status_process_data] & 0x01)) return;
    bool watched = false;
    for (unsigned n = 0; n < config_.sync_managers && !watched; ++n)
        watched = sm_enabled(n) && (memory_[reg::sm0 + reg::sm_stride * n + reg::sm_control] & reg::sm_control_watchdog_trigger);
    if (!watched) return;
    const std::uint64_t timeout_ns = (static_cast<std::uint64_t>(peek16(reg::watchdog_divider)) + 2) * clock_period_ns * ticks;
    if (pass_.port0_time_ns < watchdog_trigger_ns_ || pass_.port0_time_ns - watchdog_trigger_ns_ < timeout_ns) return;
    memory_[reg::watchdog_status_process_data] &= static_cast<std::uint8_t>(~0x01);
    // The counter saturates at 0xFF, as the datasheet's expiry counters do.
    if (memory_[reg::watchdog_counter_process_data] != 0xFF) ++memory_[reg::watchdog_counter_process_data];
    set_al_event(reg::al_event_watchdog_process_data);
}

// Reading the status from the PDI acknowledges the expiry event.
void Esc::watchdog_status_read_by_pdi() { clear_al_event(reg::al_event_watchdog_process_data); }

}  // namespace esi::esc
