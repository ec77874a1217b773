// Rules of the profile area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_profile(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
