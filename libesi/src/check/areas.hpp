#pragma once
// The rule files. Every rules_<area>[_<topic>].cpp holds whole rules: each rule's check
// function with its Rule constant (id, severity, summary, rationale, examples, check) right
// below it, and at the end of the file one add_… function listing the file's rules. The
// registry (registry.cpp) calls every add_… function once; the order does not matter, the
// catalogue is sorted by id.
//
// Adding a rule to an area touches:
//   1. its rules file: the check function, its Rule constant, one line in the file's add_… list;
//   2. tests/rules/fixtures/<rule-id>/: bad.xml (lines marked <!-- expect: <rule-id> -->) and
//      good.xml (and config.yaml for profile-… rules);
//   3. docs/rules.md, regenerated (see tests/lint/rules_doc_test.cpp).
// A new rules file adds its add_… function here and one call in registry.cpp.
#include <vector>

#include "esi/check/rule.hpp"

namespace esi::rules {

void add_xml(std::vector<Rule>& out);            // rules_xml.cpp: front-end findings (no check function)
void add_identity(std::vector<Rule>& out);       // identity-…: vendor id, product code, names, groups
void add_sm(std::vector<Rule>& out);             // sm-…: SyncManagers
void add_sm_esc(std::vector<Rule>& out);         // sm-…: what the ESC has room for (memory, SM blocks)
void add_fmmu(std::vector<Rule>& out);           // fmmu-…
void add_pdo_structure(std::vector<Rule>& out);  // pdo-…: the PDO list of a device or module
void add_pdo_entry(std::vector<Rule>& out);      // pdo-…: PDO entries on their own
void add_pdo_object(std::vector<Rule>& out);     // pdo-…: PDO entries against the Dictionary
void add_pdo_default(std::vector<Rule>& out);    // pdo-…: PDOs against the defaults of 0x1C1x, 0x16xx/0x1Axx
void add_od_type(std::vector<Rule>& out);        // od-…: DataTypes and the type names objects use
void add_od_object(std::vector<Rule>& out);      // od-…: objects, their flags and values
void add_od_structure(std::vector<Rule>& out);   // od-…: sub-index 0's type, Dictionaries per device
void add_mailbox(std::vector<Rule>& out);        // mailbox-…
void add_initcmd(std::vector<Rule>& out);        // initcmd-…
void add_dc(std::vector<Rule>& out);             // dc-…
void add_eeprom(std::vector<Rule>& out);         // eeprom-…
void add_deprecated(std::vector<Rule>& out);     // deprecated-…: CTT TF-1300 group 5
void add_profile(std::vector<Rule>& out);        // profile-…: the vendor's own limits (Limits)
void add_profile_device(std::vector<Rule>& out); // profile-…: mailbox, ESC, PDO ownership and names, parameters, SYNC0

}  // namespace esi::rules
