#pragma once
// The CoE service of the mailbox (ETG.1000.6 5.6.1): the 2-byte CoE header (number, service)
// in front of SDO requests and SDO Information requests; other services are not served.

#include <cstdint>
#include <span>
#include <vector>

#include "sim/sdo_server.hpp"

namespace esi::sim {

struct CoeReply {
    std::vector<std::vector<std::uint8_t>> frames;  // CoE frames (with their CoE header) to send
    std::uint16_t mailbox_error = 0;  // non-zero: answer with this mailbox error instead
};

class CoeServer {
public:
    CoeServer(ObjectAccess& access, bool sdo_info) : access_(access), sdo_(access), sdo_info_(sdo_info) {}

    // `request` starts at the CoE header; `room` is what a response may take after the mailbox
    // header (the CoE header included).
    [[nodiscard]] CoeReply handle(std::span<const std::uint8_t> request, AlState state, std::size_t room);
    void reset() { sdo_.reset(); }

private:
    ObjectAccess& access_;
    SdoServer sdo_;
    bool sdo_info_;
};

}  // namespace esi::sim
