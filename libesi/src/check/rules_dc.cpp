// Rules of the dc area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_dc(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
