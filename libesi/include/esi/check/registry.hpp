#pragma once
// The rule catalogue. Rules are grouped by area, one source file per area under
// libesi/src/check/; each area adds its rules in a function the registry calls.

#include <span>
#include <string_view>

#include "esi/check/rule.hpp"

namespace esi {

// Every rule, sorted by id.
[[nodiscard]] std::span<const Rule> all_rules();
[[nodiscard]] const Rule* find_rule(std::string_view id);

}  // namespace esi
