#include "fit.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "esi/sii/mapping.hpp"

namespace esi::sii {

namespace {

// A master reads the PDO assignment (0x1C12/0x1C13) and the mapping objects over CoE when the
// mailbox has CoE (IgH master/fsm_slave_scan.c: ec_fsm_pdo_start_reading after the SII walk;
// SOEM ecx_map_coe_soe); SdoInfo, PdoAssign or PdoConfig say the dictionary answers for them.
// The images SOES ships for its 256-byte EEPROMs hold no PDO categories for this reason.
bool pdos_readable_over_coe(const Device& device) {
    if (!device.mailbox || !device.mailbox->coe) return false;
    const CoeProtocol& coe = *device.mailbox->coe;
    return coe.sdo_info.value_or(false) || coe.pdo_assign.value_or(false) || coe.pdo_config.value_or(false);
}

std::size_t pdo_count(const Device& device) { return device.tx_pdos.size() + device.rx_pdos.size(); }

std::size_t unassigned_pdo_count(const Device& device) {
    auto unassigned = [](const std::vector<Pdo>& pdos) {
        return static_cast<std::size_t>(std::count_if(pdos.begin(), pdos.end(), [](const Pdo& p) { return !p.sm; }));
    };
    return unassigned(device.tx_pdos) + unassigned(device.rx_pdos);
}

// The op modes the builder writes at all: legacy modes are always left out (docs/sii.md §2.6).
std::size_t current_op_modes(const Device& device) {
    if (!device.dc) return 0;
    return static_cast<std::size_t>(
        std::count_if(device.dc->op_modes.begin(), device.dc->op_modes.end(), [](const DcOpMode& m) { return !is_legacy_op_mode(m); }));
}

std::size_t described_op_modes(const Device& device) {
    if (!device.dc) return 0;
    return static_cast<std::size_t>(std::count_if(device.dc->op_modes.begin(), device.dc->op_modes.end(),
                                                  [](const DcOpMode& m) { return !is_legacy_op_mode(m) && m.desc && !m.desc->empty(); }));
}

std::string plural(std::size_t n, std::string_view one, std::string_view many) {
    return fmt::format("{} {}", n, n == 1 ? one : many);
}

}  // namespace

std::vector<FitStep> fit_steps(const Device& device, const BuildOptions& options) {
    std::vector<FitStep> steps;
    Omissions omitted;
    const bool pdos = options.include_pdos && pdo_count(device) > 0;
    const bool dc = options.include_dc && current_op_modes(device) > 0;

    if (pdos && pdos_readable_over_coe(device)) {
        omitted.pdos = true;
        steps.push_back({fmt::format("the TxPDO and RxPDO categories ({})", plural(pdo_count(device), "PDO", "PDOs")),
                         "the CoE mailbox announces SdoInfo, PdoAssign or PdoConfig, so a master reads the PDO assignment and "
                         "mapping over CoE",
                         omitted});
    }
    if (dc && described_op_modes(device) > 0) {
        omitted.dc_descriptions = true;
        steps.push_back({fmt::format("the descriptions of the DC op modes ({})", plural(described_op_modes(device), "string", "strings")),
                         "the op modes keep their names, as in Beckhoff's own EEPROMs", omitted});
    }
    if (dc) {
        omitted.dc = true;
        steps.push_back({fmt::format("the DC category ({})", plural(current_op_modes(device), "op mode", "op modes")),
                         "masters configure DC from the ESI; IgH and SOEM do not read the category", omitted});
    }
    if (pdos && !omitted.pdos && unassigned_pdo_count(device) > 0 && unassigned_pdo_count(device) < pdo_count(device)) {
        omitted.unassigned_pdos = true;
        steps.push_back({fmt::format("the PDOs without an Sm ({}), not assigned by default",
                                     plural(unassigned_pdo_count(device), "PDO", "PDOs")),
                         "the default assignment stays complete", omitted});
    }
    if (pdos && !omitted.pdos) {
        omitted.pdos = true;
        steps.push_back({"the TxPDO and RxPDO categories",
                         "nothing else optional is left; a master then takes the process data from the ESI",
                         omitted});
    }
    // Last, the General category's optional strings, as vendor tools make their smallest images
    // (Beckhoff's BK couplers on 256-byte EEPROMs): the device name stays, masters show it.
    if (device.group_type && !device.group_type->empty()) {
        omitted.group_string = true;
        steps.push_back({fmt::format("the group name \"{}\" (General, GroupType)", *device.group_type),
                         "masters group devices by the ESI; the SII group string is for display only", omitted});
    }
    if (!device.type.text.empty()) {
        omitted.order_string = true;
        steps.push_back({fmt::format("the order number \"{}\" (General, Type)", device.type.text),
                         "a master identifies the device by vendor id, product code and revision, not by this string",
                         omitted});
    }
    if (!device.names.empty()) {
        omitted.name_string = true;
        steps.push_back({"the device name (General, Name)",
                         "the last optional string: a master names the device from the ESI it matches by identity", omitted});
    }
    return steps;
}

}  // namespace esi::sii
