#include "esi/net/network_keys.hpp"

namespace esi::net {

namespace {

constexpr std::string_view root_keys[] = {"esi", "master", "slaves"};
constexpr std::string_view master_keys[] = {"name", "cycle_time_us", "dc", "source_mac", "lcec_fork"};
constexpr std::string_view slave_keys[] = {"name",   "device",      "vendor_id", "product_code", "revision", "esi_file", "alias", "pdos",
                                           "pdo_mapping", "pdo_entries", "dc",   "modules",  "sdos",  "limits",
                                           "ros2_interfaces", "force_entries", "previous_slave", "previous_port"};
constexpr std::string_view module_keys[] = {"slot", "module"};
constexpr std::string_view ros2_interface_keys[] = {"name", "factor", "offset", "default"};
constexpr std::string_view sdo_keys[] = {"index", "subindex", "value", "type", "data", "transition", "complete_access", "comment"};

constexpr NetworkContextKeys contexts[] = {
    {NetworkContext::root, "network", root_keys},
    {NetworkContext::master, "master", master_keys},
    {NetworkContext::slave, "slave", slave_keys},
    {NetworkContext::module, "module", module_keys},
    {NetworkContext::sdo, "sdo", sdo_keys},
    {NetworkContext::ros2_interface, "ros2_interface", ros2_interface_keys},
};

}  // namespace

std::span<const NetworkContextKeys> network_contexts() { return contexts; }

const NetworkContextKeys& network_keys_of(NetworkContext context) {
    for (const NetworkContextKeys& c : contexts)
        if (c.context == context) return c;
    return contexts[0];
}

}  // namespace esi::net
