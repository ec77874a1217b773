#pragma once
// An EtherCAT frame (ETG.1000.4 §5: EtherType 0x88A4, a 2-byte EtherCAT header, then datagrams)
// passing through a line of emulated ESCs: in at slave 0's port 0, through each slave's
// processing unit, out at its port 1 to the next slave while there is one, and back.
//
// A frame is checked before any slave sees it: the header's length must fit the frame, every
// datagram must fit the header's length, the chain of "more datagrams follow" bits must end
// inside it, and the type must be 1 (EtherCAT commands). A frame that fails is dropped whole —
// nothing in it is trusted, and no slave changes state.

#include <cstdint>
#include <span>
#include <vector>

#include "esi/esc/esc.hpp"

namespace esi::esc {

inline constexpr std::uint16_t ethertype = 0x88A4;
inline constexpr std::size_t ethernet_header_bytes = 14;

// Where one datagram sits in a frame's EtherCAT payload.
struct DatagramSlot {
    std::size_t header = 0;  // offset of its 10-byte header
    std::uint16_t length = 0;
};

// The datagrams of `payload` (from the EtherCAT header on), or false when the frame is malformed.
[[nodiscard]] bool parse_frame(std::span<const std::uint8_t> payload, std::vector<DatagramSlot>& slots);

enum class FrameOutcome {
    answered,   // processed; send it back to the master
    malformed,  // dropped before any slave saw it
    lost,       // destroyed on the way (a circulating frame, or a port forced open without a link)
};

struct LineTiming {
    std::uint64_t time_ns = 0;  // when the frame reaches slave 0
    std::uint32_t hop_ns = 500; // idealised delay from one slave's port 0 to the next one's
};

// Passes the frame through `line` in order (the first ESC is the one next to the master).
// `payload` is changed in place: data read, addresses incremented, working counters, IRQ bits.
[[nodiscard]] FrameOutcome pass_frame(std::span<std::uint8_t> payload, std::span<Esc* const> line, const LineTiming& timing,
                                      std::vector<DatagramSlot>& scratch);

}  // namespace esi::esc
