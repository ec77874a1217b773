// The line's physical links (ETG.2000 Device@Physics, one letter per port: Y/H = Ethernet
// (MII), K = E-Bus). Each slave hangs off the previous one, its port A on a later port of the
// previous device of the same physics (the ENI's PreviousPort, eni_writer.cpp). An E-Bus
// terminal right after a device without an E-Bus port cannot be wired: an EtherCAT coupler
// (EK1100 or the like) is missing between them; an Ethernet device after a device with only
// E-Bus ports needs an E-Bus extension (EK1110 or the like). Both are errors: the addresses and
// PreviousPort of every later slave would be wrong on the real bus.

#include <fmt/format.h>

#include "slave_context.hpp"

namespace esi::net {

namespace {

char port_class(char c) { return c == 'K' ? 'K' : (c == 'Y' || c == 'H') ? 'Y' : c; }

bool has_later_port(const std::string& physics, char wanted) {
    for (std::size_t port = 1; port < physics.size() && port < 4; ++port)
        if (port_class(physics[port]) == wanted) return true;
    return false;
}

}  // namespace

void check_topology(const Network& network, const NetworkSpec& spec, Diagnostics& diagnostics) {
    for (std::size_t i = 1; i < network.slaves.size(); ++i) {
        const NetworkSlave& s = network.slaves[i];
        const NetworkSlave& previous = network.slaves[i - 1];
        if (s.physics.empty() || previous.physics.empty()) continue;  // the ESI does not say
        const char wanted = port_class(s.physics[0]);
        if ((wanted != 'K' && wanted != 'Y') || has_later_port(previous.physics, wanted)) continue;
        const SourcePos pos = s.position < spec.slaves.size() ? spec.slaves[s.position].pos : SourcePos{};
        const std::string what = fmt::format("'{}' ({})", s.name, s.device->type.text);
        const std::string before = fmt::format("'{}' ({}, ports '{}')", previous.name, previous.device->type.text, previous.physics);
        diagnostics.emplace(Severity::error, "net-topology",
                            wanted == 'K' ? what + " is an E-Bus terminal, but " + before +
                                                " has no E-Bus port to hang it off: an EtherCAT coupler (EK1100 or the like) is missing between them"
                                          : what + " has an Ethernet port A, but " + before +
                                                " has only E-Bus ports after its port A: an E-Bus extension (EK1110 or the like) is missing between them",
                            spec.path, pos);
    }
}

}  // namespace esi::net
