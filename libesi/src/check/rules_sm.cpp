// Rules of the sm area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_sm(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
