#include "check/sm_memory.hpp"

#include <string_view>

#include "check/sm_roles.hpp"

namespace esi::rules {

namespace {
bool role_is_mailbox(SmRole role) { return role == SmRole::mailbox_out || role == SmRole::mailbox_in; }
}  // namespace

bool has_digital_io_pdi(const Device& device) {
    if (!device.eeprom || !device.eeprom->config_data) return false;
    const std::string_view text = device.eeprom->config_data->text;
    return text.size() >= 2 && text[0] == '0' && text[1] == '4';
}

std::uint64_t default_pdo_bytes(const Device& device, std::size_t number) {
    std::uint64_t bits = 0;
    for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
        for (const auto& pdo : *list)
            if (pdo.sm && *pdo.sm == number) bits += pdo.bit_size();
    return (bits + 7) / 8;
}

std::uint64_t effective_size(const Device& device, std::size_t number) {
    const SyncManager& sm = device.sms[number];
    if (!role_is_mailbox(device_sm_role(device, sm))) {
        const std::uint64_t pdo_bytes = default_pdo_bytes(device, number);
        if (pdo_bytes > 0) return pdo_bytes;
    }
    return sm.default_size.value_or(0);
}

// Below 0x1000 Beckhoff places 1-byte buffered SMs on the digital I/O bytes 0x0F00, 0x0F01 … next
// to each other (EL2xxx, EK18xx, EM2xxx): no buffers are laid out there. A digital-I/O ESC moves
// the I/O bytes itself; the 1-byte SMs Beckhoff's digital terminals put on them take one byte each
// and sit at consecutive addresses. A mailbox SM counts as one buffer even when its ControlByte
// says buffered: that fault is sm-mailbox-mode's, and counting it again would report it twice.
bool occupies_three_buffers(const Device& device, const SyncManager& sm, std::uint64_t size) {
    if (sm.start_address && *sm.start_address < process_memory_start) return false;
    if (role_is_mailbox(device_sm_role(device, sm))) return false;
    if (size == 1 && has_digital_io_pdi(device)) return false;
    return sm.control_byte ? (*sm.control_byte & 0x03) == 0x00 : true;
}

}  // namespace esi::rules
