#include "esi/model/limits.hpp"

namespace esi {

std::optional<std::uint32_t> ParameterIndexRule::index_of(char group, std::uint32_t line) const {
    if (group < first_group || group > last_group || line >= group_size) return std::nullopt;
    const std::uint64_t index = base + std::uint64_t{group_size} * static_cast<std::uint64_t>(group - first_group) + line;
    if (index > 0xFFFF) return std::nullopt;
    return static_cast<std::uint32_t>(index);
}

std::uint64_t ParameterIndexRule::end() const {
    return base + std::uint64_t{group_size} * static_cast<std::uint64_t>(last_group - first_group + 1);
}

bool Limits::empty() const {
    return !max_rx_pdos && !max_tx_pdos && rx_pdo_ranges.empty() && tx_pdo_ranges.empty() && !max_entries_per_pdo &&
           allowed_bit_lens.empty() && fixed_sms.empty() && allowed_transitions.empty() && !max_init_cmd_bytes &&
           !max_mailbox_size && absent_objects.empty() && mailbox_protocols.empty() && !max_fmmus && !max_sms &&
           !pdo_assign && !pdo_config && !rx_pdo_name && !tx_pdo_name && !parameter_index && !sync0_cycle;
}

void Limits::merge(const Limits& other) {
    if (other.max_rx_pdos) max_rx_pdos = other.max_rx_pdos;
    if (other.max_tx_pdos) max_tx_pdos = other.max_tx_pdos;
    if (!other.rx_pdo_ranges.empty()) rx_pdo_ranges = other.rx_pdo_ranges;
    if (!other.tx_pdo_ranges.empty()) tx_pdo_ranges = other.tx_pdo_ranges;
    if (other.max_entries_per_pdo) max_entries_per_pdo = other.max_entries_per_pdo;
    if (!other.allowed_bit_lens.empty()) allowed_bit_lens = other.allowed_bit_lens;
    if (!other.fixed_sms.empty()) fixed_sms = other.fixed_sms;
    if (!other.allowed_transitions.empty()) allowed_transitions = other.allowed_transitions;
    if (other.max_init_cmd_bytes) max_init_cmd_bytes = other.max_init_cmd_bytes;
    if (other.max_mailbox_size) max_mailbox_size = other.max_mailbox_size;
    if (!other.absent_objects.empty()) absent_objects = other.absent_objects;
    if (!other.mailbox_protocols.empty()) mailbox_protocols = other.mailbox_protocols;
    if (other.max_fmmus) max_fmmus = other.max_fmmus;
    if (other.max_sms) max_sms = other.max_sms;
    if (other.pdo_assign) pdo_assign = other.pdo_assign;
    if (other.pdo_config) pdo_config = other.pdo_config;
    if (other.rx_pdo_name) rx_pdo_name = other.rx_pdo_name;
    if (other.tx_pdo_name) tx_pdo_name = other.tx_pdo_name;
    if (other.parameter_index) parameter_index = other.parameter_index;
    if (other.sync0_cycle) sync0_cycle = other.sync0_cycle;
}

}  // namespace esi
