// The checks of the way up (al_checks.hpp).

#include "sim/al_checks.hpp"

#include <algorithm>

#include "esi/ethercat/dc.hpp"
#include "esi/ethercat/sync_manager_type.hpp"
#include "esi/sii/build.hpp"
#include "esi/sii/layout.hpp"
#include "sim/al_registers.hpp"
#include "sim/al_state_machine.hpp"

namespace esi::sim {

namespace {

// Mode (bits 0–1) and direction (bits 2–3) decide what an SM is; the interrupt and watchdog bits
// are the master's choice and are not compared.
constexpr std::uint8_t mode_and_direction = 0x0F;

bool enabled(const reg::SmRegisters& r) { return (r.activate & reg::sm_activate_enable) != 0; }

std::uint16_t u16(std::uint32_t v) { return static_cast<std::uint16_t>(std::min<std::uint32_t>(v, 0xFFFF)); }

}  // namespace

DeviceExpectations device_expectations(const EtherCATInfo& info, const Device& device) {
    DeviceExpectations out;
    sii::BuildOptions options;
    const sii::BuildResult built = sii::build_image(info, device, options);
    const sii::SyncManagers* sii_sms = built.image.sync_managers();
    if (sii_sms) {
        for (std::size_t n = 0; n < sii_sms->items.size() && n < 32; ++n) {
            const sii::SyncManagerRecord& r = sii_sms->items[n];
            out.sms.push_back({static_cast<std::uint8_t>(n), ethercat::sync_manager_type_from_code(r.type).value_or(SmRole::unused),
                               r.start_address, r.length, r.control});
        }
    } else {
        for (std::size_t n = 0; n < device.sms.size() && n < 32; ++n) {
            const SyncManager& s = device.sms[n];
            out.sms.push_back({static_cast<std::uint8_t>(n), ethercat::parse_sync_manager_type(s.type).value_or(SmRole::unused),
                               u16(s.start_address.value_or(0)), u16(s.default_size.value_or(0)),
                               static_cast<std::uint8_t>(s.control_byte.value_or(0))});
        }
    }
    for (const SmExpectation& sm : out.sms) {
        std::uint32_t max_bytes = (0x10000u - std::max<std::uint32_t>(sm.start, 0x1000)) / 3u;
        if (sm.number < device.sms.size() && device.sms[sm.number].max_size) max_bytes = *device.sms[sm.number].max_size;
        out.sm_max_bits.push_back(std::min<std::uint32_t>(max_bytes, 0xFFFF) * 8u);
    }
    // The mailbox as the SII header's words 0x18–0x1B give it (what a master configures SM0 and
    // SM1 from), with the control bytes of the SM category.
    const sii::Header& h = built.image.header;
    auto mailbox = [&](SmRole role, std::uint8_t number, std::uint16_t start, std::uint16_t size, std::uint8_t control) {
        SmExpectation e{number, role, start, size, control};
        for (const SmExpectation& sm : out.sms)
            if (sm.role == role) {
                e.number = sm.number;
                e.control = sm.control;
                break;
            }
        return e;
    };
    if (device.mailbox && h.standard_receive_size > 0 && h.standard_send_size > 0) {
        out.mailbox_out = mailbox(SmRole::mailbox_out, 0, h.standard_receive_offset, h.standard_receive_size, 0x26);
        out.mailbox_in = mailbox(SmRole::mailbox_in, 1, h.standard_send_offset, h.standard_send_size, 0x22);
    }
    if (h.bootstrap_receive_size > 0 && h.bootstrap_send_size > 0) {
        out.boot_out = mailbox(SmRole::mailbox_out, 0, h.bootstrap_receive_offset, h.bootstrap_receive_size, 0x26);
        out.boot_in = mailbox(SmRole::mailbox_in, 1, h.bootstrap_send_offset, h.bootstrap_send_size, 0x22);
    }
    if (device.dc)
        for (const DcOpMode& mode : device.dc->op_modes) out.assign_activate.push_back(static_cast<std::uint16_t>(mode.assign_activate));
    return out;
}

std::uint16_t check_mailbox_sms(esc::Pdi& pdi, const SmExpectation& out, const SmExpectation& in) {
    for (const SmExpectation* e : {&out, &in}) {
        const reg::SmRegisters r = reg::read_sm(pdi, e->number, true);
        if (!enabled(r) || r.start != e->start || r.length != e->length ||
            (r.control & mode_and_direction) != (e->control & mode_and_direction))
            return al_code::invalid_mailbox_configuration;
    }
    return al_code::none;
}

std::uint16_t check_process_sm(esc::Pdi& pdi, const SmExpectation& sm, std::uint32_t bytes) {
    const reg::SmRegisters r = reg::read_sm(pdi, sm.number, true);
    const std::uint16_t wrong =
        sm.role == SmRole::outputs ? al_code::invalid_output_configuration : al_code::invalid_input_configuration;
    if (bytes == 0) return enabled(r) && r.length != 0 ? wrong : al_code::none;
    if (!enabled(r) || r.length != bytes) return wrong;
    if (r.start != sm.start || (r.control & mode_and_direction) != (sm.control & mode_and_direction))
        return al_code::invalid_sm_configuration;
    return al_code::none;
}

std::uint16_t check_dc(esc::Pdi& pdi, const std::vector<std::uint16_t>& assign_activate) {
    // The activation bits of 0x0981 as AssignActivate's high byte carries them.
    namespace aa = ethercat::assign_activate;
    constexpr std::uint16_t activation_bits = aa::cyclic_operation | aa::sync0 | aa::sync1;
    const std::uint16_t activation = reg::read_u16(pdi, reg::dc_cyclic_unit_control) & activation_bits;
    if (activation == 0) return al_code::none;
    const bool supported = std::any_of(assign_activate.begin(), assign_activate.end(),
                                       [&](std::uint16_t a) { return (a & activation_bits) == activation; });
    if (!supported) return al_code::invalid_dc_sync_configuration;
    if ((activation & aa::sync0) && reg::read_u32(pdi, reg::dc_sync0_cycle) == 0) return al_code::invalid_sync_cycle_time;
    return al_code::none;
}

}  // namespace esi::sim
