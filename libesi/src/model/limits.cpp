#include "esi/model/limits.hpp"

namespace esi {

bool Limits::empty() const {
    return !max_rx_pdos && !max_tx_pdos && rx_pdo_ranges.empty() && tx_pdo_ranges.empty() && !max_entries_per_pdo &&
           allowed_bit_lens.empty() && fixed_sms.empty() && allowed_transitions.empty() && !max_init_cmd_bytes &&
           !max_mailbox_size && absent_objects.empty();
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
}

}  // namespace esi
