#pragma once
// The view process_image.html.mustache renders (docs/esi-doc.md, "The process-image page"):
// the network, its slaves, and one picture with its variables per frame and direction.

#include <string>

#include "doc/page_context.hpp"

namespace esi::net {
struct Network;
}  // namespace esi::net

namespace esi::doc {

[[nodiscard]] ViewValue process_image_view(ViewArena& arena, const net::Network& network, std::string css);

}  // namespace esi::doc
