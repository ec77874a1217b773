// Placeholder until the ESI writer lands (branch "writer"): produces nothing.
#include "esi/xml/writer.hpp"

namespace esi {

std::string write_esi(const EsiDocument& /*document*/, const WriteOptions& /*options*/) { return {}; }

}  // namespace esi
