#pragma once
// Check functions of the pdo-… rules; rules_pdo.cpp pairs them with their catalogue entries.

#include "esi/check/rule.hpp"

namespace esi::rules::pdo {

// pdo_structure_checks.cpp: the PDO list of a device or module
void check_index_range(const EsiDocument& document, RuleContext& context);
void check_sm_unknown(const EsiDocument& document, RuleContext& context);
void check_sm_direction(const EsiDocument& document, RuleContext& context);
void check_duplicate_index(const EsiDocument& document, RuleContext& context);
void check_exclude_unknown(const EsiDocument& document, RuleContext& context);
void check_mapping_limits(const EsiDocument& document, RuleContext& context);

// pdo_entry_checks.cpp: entries on their own
void check_entry_type_unknown(const EsiDocument& document, RuleContext& context);
void check_entry_bitlen_type(const EsiDocument& document, RuleContext& context);
void check_padding_subindex(const EsiDocument& document, RuleContext& context);
void check_entry_alignment(const EsiDocument& document, RuleContext& context);

// pdo_object_checks.cpp: entries against the Dictionary
void check_entry_object_missing(const EsiDocument& document, RuleContext& context);
void check_entry_object_type(const EsiDocument& document, RuleContext& context);
void check_entry_object_bitlen(const EsiDocument& document, RuleContext& context);
void check_entry_not_mappable(const EsiDocument& document, RuleContext& context);

// pdo_default_checks.cpp: PDOs against the defaults of 0x1C1x and 0x16xx/0x1Axx
void check_assign_default(const EsiDocument& document, RuleContext& context);
void check_mapping_default(const EsiDocument& document, RuleContext& context);

}  // namespace esi::rules::pdo
