#pragma once
// A device's Sm text as the network model's SmKind, read through the protocol layer's names.

#include <string_view>

#include "esi/net/network.hpp"

namespace esi::net {

// "MBoxOut", "MBoxIn", "Outputs", "Inputs"; anything else is unused.
[[nodiscard]] SmKind sm_kind_of(std::string_view esi_type);

}  // namespace esi::net
