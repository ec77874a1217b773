// Rules of the mailbox area. See docs/rules.md for the catalogue.
#include "check/areas.hpp"

namespace esi::rules {

void add_mailbox(std::vector<Rule>& /*out*/) {}

}  // namespace esi::rules
