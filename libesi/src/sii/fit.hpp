#pragma once
// Images that fit their EEPROM the way vendor tools make them: when the whole image exceeds
// Eeprom/ByteSize, the builder leaves out optional content, one step at a time in a fixed order,
// until it fits (docs/sii.md §1, "Images larger than the EEPROM"). The mandatory part (header,
// Strings, General, FMMU, SyncM, the ESI's own Eeprom/Category entries) is never left out.

#include <string>
#include <vector>

#include "esi/model/device.hpp"
#include "esi/sii/build.hpp"

namespace esi::sii {

struct FitStep {
    std::string what;  // names what is left out, for BuildResult::left_out and the note
    std::string why;   // why a master can do without it
    Omissions omissions;  // everything left out once this step is taken (the earlier steps included)
};

// The steps that change the image of `device` under `options`, in the order they are taken:
//   1. the PDO categories of a device whose CoE mailbox announces SdoInfo, PdoAssign or
//      PdoConfig (a master reads assignment and mapping over CoE; the SOES images);
//   2. the descriptions of the DC op modes (Beckhoff's EL2262 image names its modes only);
//   3. the DC category (masters configure DC from the ESI; IgH and SOEM do not read it);
//   4. the PDOs that are not assigned by default (no @Sm);
//   5. the remaining PDO categories;
//   6. the group name string of the General category;
//   7. the order number (Type) string of the General category;
//   8. the device name string of the General category.
[[nodiscard]] std::vector<FitStep> fit_steps(const Device& device, const BuildOptions& options);

}  // namespace esi::sii
