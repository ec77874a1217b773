#include "check/sm_roles.hpp"

namespace esi::rules {

namespace {
bool has_default_pdo(const Device& device, const SyncManager& sm) {
    if (device.sms.empty() || &sm < device.sms.data() || &sm >= device.sms.data() + device.sms.size()) return false;
    const auto number = static_cast<std::uint32_t>(&sm - device.sms.data());
    for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
        for (const auto& pdo : *list)
            if (pdo.sm && *pdo.sm == number) return true;
    return false;
}
}  // namespace

SmRole text_sm_role(const SyncManager& sm) {
    const std::string_view type = sm.type;  // compared as a view: its length first
    if (type == "DynamicOutputs") return SmRole::outputs;
    if (type == "DynamicInputs") return SmRole::inputs;
    return role_from_text(type);
}

SmRole device_sm_role(const Device& device, const SyncManager& sm) {
    const SmRole from_text = text_sm_role(sm);
    if (from_text != SmRole::unknown || !sm.control_byte) return from_text;
    const bool write = control_byte_is_write(*sm.control_byte);
    if (control_byte_is_mailbox(*sm.control_byte) && !has_default_pdo(device, sm))
        return write ? SmRole::mailbox_out : SmRole::mailbox_in;
    return write ? SmRole::outputs : SmRole::inputs;
}

}  // namespace esi::rules
