#pragma once
// What the device checks on its way up (ETG.1000.6 6.4.2 and Table 11): the SyncManagers the
// master configured against the ones its SII declares, the process-data SM lengths against its
// current mapping, and the DC activation against its op modes. The expectations come from the
// SII image libesi builds for the device (what SOEM and every master read and configure from).

#include <cstdint>
#include <optional>
#include <vector>

#include "esi/esc/pdi.hpp"
#include "esi/model/ethercat_info.hpp"
#include "sim/sdo_access.hpp"

namespace esi::sim {

struct SmExpectation {
    std::uint8_t number = 0;
    SmRole role = SmRole::unused;
    std::uint16_t start = 0;
    std::uint16_t length = 0;  // mailboxes; process-data lengths follow the mapping
    std::uint8_t control = 0;
};

struct DeviceExpectations {
    std::vector<SmExpectation> sms;  // by SM number
    std::optional<SmExpectation> mailbox_out, mailbox_in;  // the standard mailbox
    std::optional<SmExpectation> boot_out, boot_in;        // the bootstrap mailbox
    std::vector<std::uint16_t> assign_activate;            // of the DC op modes; 0 = free run
    std::vector<std::uint32_t> sm_max_bits;                // by SM number
};

[[nodiscard]] DeviceExpectations device_expectations(const EtherCATInfo& info, const Device& device);

// al_code::none, or invalid_mailbox_configuration.
[[nodiscard]] std::uint16_t check_mailbox_sms(esc::Pdi& pdi, const SmExpectation& out, const SmExpectation& in);
// al_code::none, invalid_sm_configuration (start or mode), invalid_output/input_configuration
// (length or enable) for an SM that must carry `bytes`.
[[nodiscard]] std::uint16_t check_process_sm(esc::Pdi& pdi, const SmExpectation& sm, std::uint32_t bytes);
// al_code::none, invalid_dc_sync_configuration or invalid_sync_cycle_time.
[[nodiscard]] std::uint16_t check_dc(esc::Pdi& pdi, const std::vector<std::uint16_t>& assign_activate);

}  // namespace esi::sim
