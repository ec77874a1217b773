#pragma once
// The device's side of the mailbox (ETG.1000.4 and ETG.1000.6 5.5): requests read from the
// write mailbox SM (MBoxOut) when it is full, answers written into the read mailbox SM (MBoxIn)
// when it is empty, the 6-byte mailbox header with its counter (a request repeating the last
// counter is not executed again), the repeat request/acknowledge handshake (the last answer
// written again), and mailbox errors for what the device does not serve.
//
// A new request is taken only when every answer to the previous one is in MBoxIn: the write
// mailbox stays full meanwhile, so the master waits, as on a real device, and the answers
// pending are bounded by one request's.

#include <cstdint>
#include <deque>
#include <vector>

#include "esi/esc/pdi.hpp"
#include "sim/coe_server.hpp"

namespace esi::sim {

struct MailboxGeometry {
    std::uint8_t out_sm = 0;  // MBoxOut: master -> slave
    std::uint16_t out_start = 0;
    std::uint16_t out_length = 0;
    std::uint8_t in_sm = 1;   // MBoxIn: slave -> master
    std::uint16_t in_start = 0;
    std::uint16_t in_length = 0;
};

// Mailbox types (ETG.1000.6 Table 29).
namespace mailbox_type {
inline constexpr std::uint8_t error = 0;
inline constexpr std::uint8_t coe = 3;
}  // namespace mailbox_type

class MailboxServer {
public:
    // `coe` is null for a device without CoE (every request then gets a mailbox error).
    MailboxServer(MailboxGeometry geometry, CoeServer* coe) : geometry_(geometry), coe_(coe) {}

    void poll(esc::Pdi& pdi, AlState state);
    // Back to power-on: nothing pending, counters cleared (AL state INIT).
    void reset();
    [[nodiscard]] const MailboxGeometry& geometry() const { return geometry_; }

private:
    void handle(const std::vector<std::uint8_t>& request, AlState state);
    void send(std::uint8_t type, const std::vector<std::uint8_t>& payload);
    void send_error(std::uint16_t detail);

    MailboxGeometry geometry_;
    CoeServer* coe_;
    std::deque<std::vector<std::uint8_t>> pending_;  // whole mailbox buffers, ready to write
    std::vector<std::uint8_t> last_written_;
    std::uint8_t last_request_counter_ = 0;  // 0: none since reset
    std::uint8_t counter_ = 0;               // of the answers, 1..7
};

}  // namespace esi::sim
