// Rules of the identity area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_identity(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
