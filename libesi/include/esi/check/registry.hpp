#pragma once
// The rule catalogue. Each rule is defined next to its check in a rules file under
// libesi/src/check/ (rules_<area>[_<topic>].cpp); libesi/src/check/areas.hpp says how a rule is
// added and registered.

#include <span>
#include <string_view>

#include "esi/check/rule.hpp"

namespace esi {

// Every rule, sorted by id.
[[nodiscard]] std::span<const Rule> all_rules();
[[nodiscard]] const Rule* find_rule(std::string_view id);
// The rule id nearest to a misspelt one ("did you mean …?"); empty when none is close.
[[nodiscard]] std::string_view nearest_rule_id(std::string_view id);

}  // namespace esi
