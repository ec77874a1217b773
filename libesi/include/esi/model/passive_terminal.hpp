#pragma once
// A passive terminal (Beckhoff EL9xxx end, supply and shield terminals) has no ESC, so no EtherCAT
// identity (Type without ProductCode and RevisionNo) and nothing an ESC would serve: no SM, FMMU,
// mailbox, PDO, DC, dictionary, slots or EEPROM. It is not a duplicate identity and gets no SII
// image (docs/yaml-format.md, "Devices").

#include "esi/model/device.hpp"

namespace esi {

[[nodiscard]] bool is_passive_terminal(const Device& device);

}  // namespace esi
