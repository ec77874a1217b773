// Rules of the deprecated area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_deprecated(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
