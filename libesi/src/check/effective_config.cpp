#include "esi/check/effective_config.hpp"

#include <algorithm>

namespace esi {

const Limits& EffectiveConfig::limits_for(std::optional<std::uint32_t> product_code) const {
    if (product_code)
        for (const auto& [codes, device_limits_entry] : device_limits)
            if (std::find(codes.begin(), codes.end(), *product_code) != codes.end()) return device_limits_entry;
    return limits;
}

std::optional<Severity> EffectiveConfig::severity_of(std::string_view rule_id, Severity default_severity) const {
    const auto it = rules.find(rule_id);
    if (it == rules.end()) return default_severity;
    switch (it->second) {
        case RuleSetting::off: return std::nullopt;
        case RuleSetting::info: return Severity::info;
        case RuleSetting::warning: return Severity::warning;
        case RuleSetting::error: return Severity::error;
    }
    return default_severity;
}

}  // namespace esi
