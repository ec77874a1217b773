// The bus's physical links (ETG.2000 Device@Physics, one letter per port A–D: Y/H = Ethernet
// (MII), K = E-Bus). Each slave hangs off an earlier one: by default the one listed before it,
// on that device's first free port after A of the same physics; `previous_slave:` and
// `previous_port:` hang it off a junction's or coupler's other port (EK1122, a 3-port EBC), so
// the network is a tree. The result is the ENI's PreviousPort (eni_writer.cpp).
//
// Everything a master derives from the order is checked, not guessed: the port must exist on the
// device, carry the same physics as the slave's port A (an E-Bus terminal on an Ethernet port
// cannot be wired: the error names the missing coupler or extension), and serve one slave only.
// The list must be in the order the frame meets the slaves, since station and auto-increment
// addresses follow the list: an ESC forwards a frame through its ports in the order A, D, B, C
// (0 → 3 → 1 → 2, the frame processing order of the Beckhoff ESC datasheets), so a device's
// branch on port D comes before its branch on B, and B's before C's.

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "slave_context.hpp"

namespace esi::net {

namespace {

char port_class(char c) { return c == 'K' ? 'K' : (c == 'Y' || c == 'H') ? 'Y' : c; }

char port_letter(std::size_t port) { return static_cast<char>('A' + port); }

// Where a port's branch comes in the frame's path through the device: D, then B, then C.
int visit_rank(std::size_t port) { return port == 3 ? 0 : static_cast<int>(port); }

bool has_later_port(const std::string& physics, char wanted) {
    for (std::size_t port = 1; port < physics.size() && port < 4; ++port)
        if (port_class(physics[port]) == wanted) return true;
    return false;
}

std::string described(const NetworkSlave& s) { return fmt::format("'{}' ({})", s.name, s.device->type.text); }

std::string with_ports(const NetworkSlave& s) {
    return fmt::format("'{}' ({}, ports '{}')", s.name, s.device->type.text, s.physics);
}

const char* physics_name(char cls) { return cls == 'K' ? "E-Bus" : "Ethernet"; }

class Topology {
public:
    Topology(Network& network, const NetworkSpec& spec, Diagnostics& diagnostics) : net_(network), spec_(spec), diagnostics_(diagnostics) {}

    void run() {
        bool linked = true;
        for (std::size_t i = 0; i < net_.slaves.size(); ++i) linked = link(i) && linked;
        if (linked) check_order();
    }

private:
    const SlaveSpec& spec_of(const NetworkSlave& s) const { return spec_.slaves[s.position]; }

    void error(SourcePos pos, std::string message) { diagnostics_.emplace(Severity::error, "net-topology", std::move(message), spec_.path, pos); }

    std::optional<std::size_t> upstream(std::size_t i) {
        const NetworkSlave& s = net_.slaves[i];
        const SlaveSpec& ss = spec_of(s);
        if (!ss.previous_slave) return i - 1;
        for (std::size_t j = 0; j < net_.slaves.size(); ++j) {
            if (net_.slaves[j].name != *ss.previous_slave) continue;
            if (j == i) {
                error(ss.previous_slave_pos, fmt::format("'{}' cannot hang off itself", s.name));
                return std::nullopt;
            }
            if (j > i) {
                error(ss.previous_slave_pos,
                      fmt::format("'{}' hangs off '{}', which is listed after it: the frame reaches a slave's upstream neighbour "
                                  "first, so list '{}' before '{}'",
                                  s.name, *ss.previous_slave, *ss.previous_slave, s.name));
                return std::nullopt;
            }
            return j;
        }
        // A slave the network names but could not configure was reported already.
        for (const SlaveSpec& other : spec_.slaves)
            if (other.name == *ss.previous_slave) return std::nullopt;
        error(ss.previous_slave_pos, fmt::format("previous_slave '{}' names no slave of the network", *ss.previous_slave));
        return std::nullopt;
    }

    bool link(std::size_t i) {
        NetworkSlave& s = net_.slaves[i];
        const SlaveSpec& ss = spec_of(s);
        if (i == 0) {
            if (ss.previous_slave || ss.previous_port) {
                error(ss.previous_slave ? ss.previous_slave_pos : ss.previous_port_pos,
                      fmt::format("'{}' is the first slave: it hangs off the master, not off another slave's port", s.name));
                return false;
            }
            return true;
        }
        const std::optional<std::size_t> up = upstream(i);
        if (!up) return false;
        const NetworkSlave& previous = net_.slaves[*up];
        const char wanted = s.physics.empty() ? 0 : port_class(s.physics[0]);
        const bool checked = wanted && !previous.physics.empty() && (wanted == 'K' || wanted == 'Y');
        std::size_t port = 0;
        if (ss.previous_port) {
            const std::string& p = *ss.previous_port;
            if (p.size() != 1 || p[0] < 'B' || p[0] > 'D') {
                error(ss.previous_port_pos, fmt::format("previous_port is B, C or D (A is the port towards the master), not '{}'", p));
                return false;
            }
            port = static_cast<std::size_t>(p[0] - 'A');
            if (!previous.physics.empty() && port >= previous.physics.size()) {
                error(ss.previous_port_pos, fmt::format("{} has no port {}", with_ports(previous), p));
                return false;
            }
            if (checked && port_class(previous.physics[port]) != wanted) {
                error(ss.previous_port_pos,
                      fmt::format("port {} of {} is {}, but {} connects by {} (its port A is '{}')", p, with_ports(previous),
                                  physics_name(port_class(previous.physics[port])), described(s), physics_name(wanted), s.physics[0]));
                return false;
            }
        } else {
            port = first_free_port(*up, previous, wanted, checked);
            if (port == 0) {
                if (checked && !has_later_port(previous.physics, wanted)) {
                    missing_link(s, previous, wanted);
                } else {
                    error(ss.pos, fmt::format("every port of {} that {} could use is taken ({}); hang it off another slave with "
                                              "previous_slave",
                                              with_ports(previous), described(s), users_of(*up)));
                }
                return false;
            }
        }
        if (const auto taken = used_.find({*up, port}); taken != used_.end()) {
            error(ss.previous_port ? ss.previous_port_pos : ss.pos,
                  fmt::format("port {} of '{}' is taken by '{}' already; one port carries one link", port_letter(port), previous.name,
                              net_.slaves[taken->second].name));
            return false;
        }
        used_[{*up, port}] = i;
        s.previous = *up;
        s.previous_port = port;
        return true;
    }

    // The first port after A (B, C, D) of the wanted physics that no slave uses yet; 0 when none.
    std::size_t first_free_port(std::size_t up, const NetworkSlave& previous, char wanted, bool checked) const {
        const std::size_t ports = previous.physics.empty() ? 4 : std::min<std::size_t>(previous.physics.size(), 4);
        // A slave whose ESI gives no physics is taken for Ethernet first (the old line rule).
        const char preferred = checked ? wanted : 'Y';
        for (std::size_t port = 1; port < ports; ++port) {
            if (!previous.physics.empty() && port_class(previous.physics[port]) != preferred) continue;
            if (!used_.contains({up, port})) return port;
        }
        if (checked) return 0;
        for (std::size_t port = 1; port < ports; ++port)
            if (!used_.contains({up, port})) return port;
        return 0;
    }

    std::string users_of(std::size_t up) const {
        std::string out;
        for (const auto& [key, child] : used_)
            if (key.first == up) out += fmt::format("{}port {}: '{}'", out.empty() ? "" : ", ", port_letter(key.second), net_.slaves[child].name);
        return out;
    }

    void missing_link(const NetworkSlave& s, const NetworkSlave& previous, char wanted) {
        const std::string what = described(s), before = with_ports(previous);
        error(spec_of(s).pos,
              wanted == 'K' ? what + " is an E-Bus terminal, but " + before +
                                  " has no E-Bus port to hang it off: an EtherCAT coupler (EK1100 or the like) is missing between them"
                            : what + " has an Ethernet port A, but " + before +
                                  " has only E-Bus ports after its port A: an E-Bus extension (EK1110 or the like) is missing between them");
    }

    // The order the frame meets the slaves: depth first from the first, each device's branches
    // in its ports' visiting order (D, B, C). It must be the list's order.
    void check_order() {
        std::vector<std::vector<std::size_t>> children(net_.slaves.size());
        for (std::size_t i = 1; i < net_.slaves.size(); ++i) children[*net_.slaves[i].previous].push_back(i);
        for (auto& c : children)
            std::stable_sort(c.begin(), c.end(), [&](std::size_t a, std::size_t b) {
                return visit_rank(net_.slaves[a].previous_port) < visit_rank(net_.slaves[b].previous_port);
            });
        std::vector<std::size_t> order, stack{0};
        while (!stack.empty() && !net_.slaves.empty()) {
            const std::size_t at = stack.back();
            stack.pop_back();
            order.push_back(at);
            for (auto it = children[at].rbegin(); it != children[at].rend(); ++it) stack.push_back(*it);
        }
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (order[k] == k) continue;
            const NetworkSlave& met = net_.slaves[order[k]];
            const NetworkSlave& listed = net_.slaves[k];
            error(spec_of(met).pos,
                  fmt::format("'{}' is listed as slave {}, but the frame reaches it as slave {}, before '{}': an ESC forwards the "
                              "frame through its ports in the order A, D, B, C (0, 3, 1, 2), so the branch on port {} of '{}' comes "
                              "first; list the slaves in that order (their station and auto-increment addresses follow it)",
                              met.name, order[k] + 1, k + 1, listed.name, port_letter(met.previous_port),
                              net_.slaves[*met.previous].name));
            return;
        }
    }

    Network& net_;
    const NetworkSpec& spec_;
    Diagnostics& diagnostics_;
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> used_;  // (slave, port) -> the slave on it
};

}  // namespace

void resolve_topology(Network& network, const NetworkSpec& spec, Diagnostics& diagnostics) { Topology(network, spec, diagnostics).run(); }

}  // namespace esi::net
