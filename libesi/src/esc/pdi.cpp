#include "esi/esc/pdi.hpp"

namespace esi::esc {

// Out of line, so that the vtables of both interfaces live in this layer.
Pdi::~Pdi() = default;
SlaveStack::~SlaveStack() = default;

}  // namespace esi::esc
