#include "esi/check/run.hpp"

#include "check/rule_cache.hpp"
#include "esi/check/registry.hpp"

namespace esi {

Diagnostics run_rules(const EsiDocument& document, const EffectiveConfig& config) {
    Diagnostics out;
    rules::RuleCache cache;
    for (const Rule& rule : all_rules()) {
        if (!rule.check) continue;
        const std::optional<Severity> severity = config.severity_of(rule.id, rule.default_severity);
        if (!severity) continue;
        RuleContext context(document, rule, *severity, config, out, &cache);
        rule.check(document, context);
    }
    return out;
}

}  // namespace esi
