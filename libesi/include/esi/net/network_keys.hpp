#pragma once
// The keys of every mapping in NETWORK.yaml, one table per context, as esi/yaml/format_keys.hpp
// does for device sources. The reader checks mappings against these tables (unknown key ->
// did-you-mean), and a test checks that schemas/esi-network.schema.json declares exactly these
// keys, so parser, schema and docs/esi-net.md cannot drift apart.

#include <span>
#include <string_view>

namespace esi::net {

enum class NetworkContext { root, master, slave, module, sdo, ros2_interface };

struct NetworkContextKeys {
    NetworkContext context;
    std::string_view name;  // the $defs name in the JSON Schema ("network" for the root)
    std::span<const std::string_view> keys;
};

[[nodiscard]] std::span<const NetworkContextKeys> network_contexts();
[[nodiscard]] const NetworkContextKeys& network_keys_of(NetworkContext context);

}  // namespace esi::net
