#include "esi/model/passive_terminal.hpp"

namespace esi {

bool is_passive_terminal(const Device& device) {
    return !device.type.product_code && !device.type.revision_no && device.sms.empty() && device.fmmus.empty() &&
           device.sus.empty() && !device.mailbox && device.rx_pdos.empty() && device.tx_pdos.empty() && !device.dc &&
           device.profiles.empty() && !device.slots && !device.eeprom;
}

}  // namespace esi
