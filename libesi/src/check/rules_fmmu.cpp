// Rules of the fmmu area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_fmmu(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
