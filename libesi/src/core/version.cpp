#include "esi/version.hpp"

namespace esi {
std::string_view version() { return ESI_VERSION; }
}  // namespace esi
