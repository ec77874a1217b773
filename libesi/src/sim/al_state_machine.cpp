// The AL state machine (al_state_machine.hpp).

#include "sim/al_state_machine.hpp"

#include "sim/al_registers.hpp"

namespace esi::sim {

namespace {

constexpr std::uint16_t control_state_mask = ethercat::al_state_mask;
constexpr std::uint16_t control_acknowledge = ethercat::al_error_bit;
constexpr std::uint16_t control_identify = 0x0020;
constexpr std::uint16_t status_error = ethercat::al_error_bit;
constexpr std::uint16_t status_id_loaded = 0x0020;

bool is_state(std::uint16_t code) { return ethercat::al_state_from_bits(code).has_value() && code <= control_state_mask; }

// ETG.1000.6 Table 10: the transitions a slave accepts (besides staying where it is).
bool transition_exists(AlState from, AlState to) { return ethercat::is_state_machine_transition({from, to}); }

}  // namespace

int al_rank(AlState state) {
    switch (state) {
        case AlState::init: return 0;
        case AlState::preop:
        case AlState::boot: return 1;
        case AlState::safeop: return 2;
        case AlState::op: return 3;
    }
    return 0;
}

void AlStateMachine::write_status(esc::Pdi& pdi, bool identify) {
    std::uint16_t status = static_cast<std::uint16_t>(state_);
    if (error_) status |= status_error;
    std::uint16_t code = code_;
    // Explicit device identification (ETG.1000.6 6.4.1.2): the ID, here the configured station
    // alias, goes in the AL status code while no error is shown.
    if (identify && !error_) {
        status |= status_id_loaded;
        code = reg::read_u16(pdi, reg::station_alias);
    }
    reg::write_u16(pdi, reg::al_status_code, code);
    reg::write_u16(pdi, reg::al_status, status);
}

void AlStateMachine::local_error(esc::Pdi& pdi, AlState to, std::uint16_t code) {
    state_ = to;
    error_ = true;
    code_ = code;
    write_status(pdi, false);
}

void AlStateMachine::poll(esc::Pdi& pdi, AlTransitions& device) {
    if (!started_) {
        started_ = true;
        write_status(pdi, false);
    }
    if (!(reg::read_u32(pdi, reg::al_event_request) & reg::al_event_al_control)) return;
    const std::uint16_t control = reg::read_u16(pdi, reg::al_control);  // clears the event
    const std::uint16_t requested = control & control_state_mask;
    const bool acknowledge = (control & control_acknowledge) != 0;
    const bool identify = (control & control_identify) != 0;

    if (error_ && !acknowledge && (!is_state(requested) || al_rank(static_cast<AlState>(requested)) >= al_rank(state_))) {
        write_status(pdi, false);
        return;
    }
    if (acknowledge) {
        error_ = false;
        code_ = al_code::none;
    }
    auto refuse = [&](std::uint16_t code) {
        error_ = true;
        code_ = code;
        write_status(pdi, false);
    };
    if (!is_state(requested)) return refuse(al_code::unknown_state);
    const auto to = static_cast<AlState>(requested);
    if (to != state_) {
        if (!transition_exists(state_, to)) return refuse(al_code::invalid_state_change);
        if (const std::uint16_t code = device.check(pdi, state_, to); code != al_code::none) return refuse(code);
        const AlState from = state_;
        state_ = to;
        device.entered(pdi, from, to);
    }
    write_status(pdi, identify);
}

}  // namespace esi::sim
