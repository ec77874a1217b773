// A line of virtual slaves: the frame through every ESC, then one iteration of every stack.

#include "esi/sim/line.hpp"

namespace esi::sim {

void Line::add(VirtualSlave slave) {
    slaves_.push_back(std::move(slave));
    escs_.push_back(slaves_.back().esc.get());
}

esc::FrameOutcome Line::process(std::span<std::uint8_t> payload, std::uint64_t time_ns) {
    const esc::FrameOutcome outcome = esc::pass_frame(payload, escs_, {time_ns, hop_ns}, scratch_);
    if (outcome != esc::FrameOutcome::malformed) poll();
    return outcome;
}

void Line::poll() {
    // PDI control 0 means the microcontroller has no interface to the ESC, and a configuration
    // area that failed its checksum leaves the PDI off: the stack never runs (ESC datasheet
    // 0x0140, 0x0110 bit 0).
    for (VirtualSlave& slave : slaves_)
        if (slave.stack && slave.esc->pdi_active()) slave.stack->poll(*slave.esc);
}

}  // namespace esi::sim
