#pragma once
// Check functions of the profile-… rules: one per field of Limits (esi/model/limits.hpp). They
// only fire when the effective .esi-lint.yaml sets that limit for the device.

#include "esi/check/rule.hpp"

namespace esi::rules::profile {

void check_max_pdos(const EsiDocument& document, RuleContext& context);
void check_pdo_index_range(const EsiDocument& document, RuleContext& context);
void check_max_entries(const EsiDocument& document, RuleContext& context);
void check_bitlen(const EsiDocument& document, RuleContext& context);
void check_fixed_sm(const EsiDocument& document, RuleContext& context);
void check_initcmd_transition(const EsiDocument& document, RuleContext& context);
void check_initcmd_size(const EsiDocument& document, RuleContext& context);
void check_mailbox_size(const EsiDocument& document, RuleContext& context);
void check_absent_object(const EsiDocument& document, RuleContext& context);

}  // namespace esi::rules::profile
