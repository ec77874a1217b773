// Rules of the eeprom area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_eeprom(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
