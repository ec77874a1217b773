#pragma once
// Running the rule catalogue over one document: every rule the config enables, at the severity
// it sets. The rules share one cache of Dictionary indexes and object layouts for the run.

#include "esi/check/effective_config.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

[[nodiscard]] Diagnostics run_rules(const EsiDocument& document, const EffectiveConfig& config);

}  // namespace esi
