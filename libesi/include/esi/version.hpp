#pragma once
#include <string_view>

namespace esi {
// The library version (CMake project version).
[[nodiscard]] std::string_view version();
}  // namespace esi
