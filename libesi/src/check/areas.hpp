#pragma once
// One function per rule area; each lives in rules_<area>.cpp and appends that area's rules.
#include <vector>

#include "esi/check/rule.hpp"

namespace esi::rules {

void add_xml(std::vector<Rule>& out);         // front-end findings: syntax, encoding, numbers
void add_identity(std::vector<Rule>& out);    // identity-…: vendor id, product code, names, groups
void add_sm(std::vector<Rule>& out);          // sm-…: SyncManagers
void add_fmmu(std::vector<Rule>& out);        // fmmu-…
void add_pdo(std::vector<Rule>& out);         // pdo-…: PDOs and entries
void add_od(std::vector<Rule>& out);          // od-…: Dictionary types and objects
void add_mailbox(std::vector<Rule>& out);     // mailbox-…
void add_initcmd(std::vector<Rule>& out);     // initcmd-…
void add_dc(std::vector<Rule>& out);          // dc-…
void add_eeprom(std::vector<Rule>& out);      // eeprom-…
void add_deprecated(std::vector<Rule>& out);  // deprecated-…: CTT TF-1300 group 5
void add_profile(std::vector<Rule>& out);     // profile-…: the vendor's own limits (Limits)

}  // namespace esi::rules
