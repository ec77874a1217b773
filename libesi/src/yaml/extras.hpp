#pragma once
// The escape hatch for XML the model does not cover (vendor-specific elements, Info, ESC …):
//
//   xml:
//     attributes: { CheckRevisionNo: EQ_OR_G }
//     elements:
//       - <Info><StateMachine><Timeout><PreopTimeout>2000</PreopTimeout></Timeout></StateMachine></Info>
//       - { after: Mailbox, xml: "<VendorSpecific><Tool>x</Tool></VendorSpecific>" }
//
// Elements are verbatim XML text parsed into Extras (with `after` naming the element they follow,
// as the XML reader records it), so an imported ESI can say everything its model holds.

#include <string_view>

#include "esi/yaml/tree.hpp"

#include "esi/model/common.hpp"
#include "esi/yaml/reader.hpp"

namespace esi::yaml {

void read_extras(Reader& reader, const Node& node, Extras& out, std::string_view what);

}  // namespace esi::yaml
