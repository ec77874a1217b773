// Rules of the initcmd area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_initcmd(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
