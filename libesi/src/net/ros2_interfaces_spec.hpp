#pragma once
// Reads a slave's `ros2_interfaces:` in NETWORK.yaml (docs/esi-net.md): keys INDEX:SUBINDEX,
// values an interface name, `~` (no interface), or a mapping {name, factor, offset, default}.

#include <vector>

#include "esi/net/network_spec.hpp"
#include "esi/yaml/reader.hpp"

namespace esi::net {

[[nodiscard]] std::vector<Ros2InterfaceSpec> read_ros2_interfaces(yaml::Reader& reader, const yaml::Node& node);

}  // namespace esi::net
