#pragma once
// esi-sim on a network interface: a raw AF_PACKET socket bound to EtherType 0x88A4, each frame
// passed through the line and sent back, as a line of real ESCs returns it to the master.
// Linux only.

#include <atomic>
#include <functional>
#include <string>

#include "esi/diagnostic.hpp"
#include "esi/sim/line.hpp"

namespace esi::sim {

struct ServeStats {
    std::uint64_t answered = 0;
    std::uint64_t dropped = 0;  // malformed or lost on the way
};

// Opens the socket on `interface` (an unknown interface, or no permission for raw sockets: an
// error with the reason, and `ready` is never called), calls `ready` once it receives, then
// answers frames until `stop` becomes true (checked at least every 100 ms).
[[nodiscard]] Diagnostics serve_interface(Line& line, const std::string& interface, const std::atomic<bool>& stop,
                                          const std::function<void()>& ready, ServeStats* stats = nullptr);

}  // namespace esi::sim
