#pragma once
// A line of virtual slaves: each an emulated ESC with the slave stack that runs on it, in bus
// order (slave 0 next to the master). A frame passes through every slave and back
// (esc::pass_frame); after each frame every slave stack whose ESC has an active PDI runs one
// iteration, so it has answered before the master's next frame.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "esi/esc/esc.hpp"
#include "esi/esc/frame.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::sim {

struct VirtualSlave {
    std::string name;  // the device's Type text
    std::uint32_t vendor_id = 0, product_code = 0, revision = 0;
    std::unique_ptr<esc::Esc> esc;
    std::unique_ptr<esc::SlaveStack> stack;  // null: an ESC without firmware
};

class Line {
public:
    Line() = default;
    Line(Line&&) noexcept = default;
    Line& operator=(Line&&) noexcept = default;

    void add(VirtualSlave slave);
    // Keeps the documents the slaves' devices (and their stacks) point into alive.
    void keep(std::shared_ptr<const EsiDocument> document) { documents_.push_back(std::move(document)); }

    // One EtherCAT frame (from the EtherCAT header on), changed in place; then the stacks run.
    esc::FrameOutcome process(std::span<std::uint8_t> payload, std::uint64_t time_ns);
    // Runs every active stack once more without a frame (a stack that waits for itself).
    void poll();

    [[nodiscard]] std::size_t size() const { return slaves_.size(); }
    [[nodiscard]] VirtualSlave& slave(std::size_t i) { return slaves_[i]; }
    [[nodiscard]] const VirtualSlave& slave(std::size_t i) const { return slaves_[i]; }
    // The idealised delay of one hop along the line (DC receive times).
    std::uint32_t hop_ns = 500;

private:
    std::vector<std::shared_ptr<const EsiDocument>> documents_;
    std::vector<VirtualSlave> slaves_;
    std::vector<esc::Esc*> escs_;
    std::vector<esc::DatagramSlot> scratch_;
};

}  // namespace esi::sim
