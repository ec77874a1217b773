#pragma once
// Reads a slave's `ros2_interfaces:` in NETWORK.yaml (docs/esi-net.md): keys INDEX:SUBINDEX,
// values an interface name, `~` (no interface), or a mapping {name, factor, offset, default}.

#include <vector>

#include "esi/net/network_spec.hpp"
#include "esi/yaml/reader.hpp"

namespace esi::net {

[[nodiscard]] std::vector<Ros2InterfaceSpec> read_ros2_interfaces(yaml::Reader& reader, const yaml::Node& node);

// "0x6000:0x01" or "0x6000:1": an entry's index (1..0xFFFF) and sub-index.
[[nodiscard]] bool parse_entry_key(std::string_view text, std::uint32_t& index, std::uint32_t& subindex);

// force_entries: a list of INDEX:SUBINDEX (forced_entries.cpp).
[[nodiscard]] std::vector<ForcedEntry> read_forced_entries(yaml::Reader& reader, const yaml::Node& node);

}  // namespace esi::net
