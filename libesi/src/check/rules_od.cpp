// Rules of the od area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_od(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
