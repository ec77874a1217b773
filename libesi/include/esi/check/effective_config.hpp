#pragma once
// The rule settings and limits that apply to one file once .esi-lint.yaml and its overrides
// have been resolved.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "esi/model/limits.hpp"
#include "esi/diagnostic.hpp"

namespace esi {

enum class RuleSetting { off, info, warning, error };

struct EffectiveConfig {
    std::map<std::string, RuleSetting, std::less<>> rules;  // absent: the rule's default
    Limits limits;
    std::vector<std::pair<std::vector<std::uint32_t>, Limits>> device_limits;  // product codes -> limits

    [[nodiscard]] const Limits& limits_for(std::optional<std::uint32_t> product_code) const;
    // nullopt: the rule is off.
    [[nodiscard]] std::optional<Severity> severity_of(std::string_view rule_id, Severity default_severity) const;
};

}  // namespace esi
