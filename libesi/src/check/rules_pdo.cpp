// Rules of the pdo area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_pdo(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
