#pragma once
// The AL state machine of the device (ETG.1000.6 6.4): the master requests a state in AL control
// (0x0120), the device answers in AL status (0x0130) and, when it refuses, sets the error
// indication with a code in AL status code (0x0134). Which transitions exist is fixed here; what
// a device checks on the way up (SyncManagers, mapping, DC) is asked of AlTransitions.
//
// Error indication: while it is set, requests for the same or a higher state without the
// acknowledge bit (0x0120 bit 4) are not acted on; a lower state is entered and the indication
// stays until acknowledged.

#include <cstdint>

#include "esi/esc/pdi.hpp"
#include "esi/ethercat/al_state.hpp"
#include "sim/coe_dictionary.hpp"

namespace esi::sim {

// AL status codes (ETG.1000.6 Table 11): the protocol layer's.
namespace al_code = ethercat::al_code;

class AlTransitions {
public:
    virtual ~AlTransitions() = default;
    // al_code::none when the device may go from `from` up or down to `to`, else the refusal.
    [[nodiscard]] virtual std::uint16_t check(esc::Pdi& pdi, AlState from, AlState to) = 0;
    // Called once the device is in `to`.
    virtual void entered(esc::Pdi& pdi, AlState from, AlState to) = 0;
};

class AlStateMachine {
public:
    // Reacts to an AL control event, if there is one; writes the AL status at the first call.
    void poll(esc::Pdi& pdi, AlTransitions& device);
    // The device leaves its state on its own (a local error such as an expired watchdog): it
    // goes to `to` with the error indication and `code`, which the master acknowledges.
    void local_error(esc::Pdi& pdi, AlState to, std::uint16_t code);
    [[nodiscard]] AlState state() const { return state_; }
    [[nodiscard]] bool error() const { return error_; }
    [[nodiscard]] std::uint16_t code() const { return code_; }

private:
    void write_status(esc::Pdi& pdi, bool identify);

    AlState state_ = AlState::init;
    bool error_ = false;
    std::uint16_t code_ = al_code::none;
    bool started_ = false;
};

// The rank of a state on the way up (BOOT stands beside PREOP): INIT 0,
// PREOP and BOOT 1, SAFEOP 2, OP 3.
[[nodiscard]] int al_rank(AlState state);

}  // namespace esi::sim
