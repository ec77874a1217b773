#pragma once
// Check functions of the od-… rules; rules_od.cpp pairs them with their catalogue entries.

#include "esi/check/rule.hpp"

namespace esi::rules::od {

// od_type_checks.cpp: DataTypes and the type names objects use
void check_type_unresolved(const EsiDocument& document, RuleContext& context);
void check_type_cycle(const EsiDocument& document, RuleContext& context);
void check_nonstandard_type_name(const EsiDocument& document, RuleContext& context);
void check_subitem_layout(const EsiDocument& document, RuleContext& context);
void check_array_size(const EsiDocument& document, RuleContext& context);
void check_bitsize(const EsiDocument& document, RuleContext& context);
void check_duplicate_datatype(const EsiDocument& document, RuleContext& context);

// od_object_checks.cpp: objects, their flags and values
void check_mandatory_object(const EsiDocument& document, RuleContext& context);
void check_duplicate_object(const EsiDocument& document, RuleContext& context);
void check_flags_value(const EsiDocument& document, RuleContext& context);
void check_default_length(const EsiDocument& document, RuleContext& context);
void check_default_range(const EsiDocument& document, RuleContext& context);

}  // namespace esi::rules::od
