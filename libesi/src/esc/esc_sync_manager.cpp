// SyncManagers (ESC datasheet section I "SyncManager", section II 0x0800+): mailbox mode (one
// buffer, handshake through full/empty) and buffered mode (three buffers, the newest complete
// one always available to the reader). An access opens a buffer at its first byte and completes
// it at its last byte, on either side.

#include <algorithm>
#include <cstring>

#include "esi/esc/esc.hpp"
#include "esi/ethercat/registers.hpp"

namespace esi::esc {

namespace reg = ethercat::reg;

namespace {

[[nodiscard]] std::uint32_t sm_base(unsigned n) { return reg::sm0 + reg::sm_stride * n; }

}  // namespace

std::uint16_t Esc::sm_start(unsigned n) const { return peek16(static_cast<std::uint16_t>(sm_base(n) + reg::sm_start)); }

std::uint16_t Esc::sm_length(unsigned n) const {
    // A buffered SM occupies three times its length; all of it must lie in the address space.
    const std::uint32_t length = peek16(static_cast<std::uint16_t>(sm_base(n) + reg::sm_length));
    const std::uint32_t copies = (memory_[sm_base(n) + reg::sm_control] & reg::sm_mode_mask) == reg::sm_mode_mailbox ? 1 : 3;
    if (sm_start(n) + length * copies > 0x10000) return 0;
    return static_cast<std::uint16_t>(length);
}

bool Esc::sm_enabled(unsigned n) const {
    const std::uint32_t base = sm_base(n);
    return (memory_[base + reg::sm_activate] & reg::sm_activate_enable) &&
           !(memory_[base + reg::sm_pdi_control] & reg::sm_pdi_deactivate) && sm_length(n) > 0;
}

// Who writes an SM follows its direction: ECAT writes MBoxOut and outputs, the PDI writes MBoxIn
// and inputs. A mailbox refuses a write while full and a read while empty (no working counter);
// the side that does not own a direction may not touch a mailbox at all. A buffered SM lets the
// writer's side read the newest buffer back (no side effects) but ignores the reader's writes.
bool Esc::sm_accepts(Side side, bool is_write, unsigned n) const {
    const std::uint8_t control = memory_[sm_base(n) + reg::sm_control];
    const bool ecat_writes = (control & reg::sm_direction_mask) == reg::sm_direction_ecat_writes;
    const bool writer = (side == Side::ecat) == ecat_writes;
    if ((control & reg::sm_mode_mask) == reg::sm_mode_mailbox) {
        if (writer) return is_write ? !sms_[n].full : side == Side::pdi;
        return !is_write && sms_[n].full;
    }
    return writer || !is_write;
}

void Esc::sm_transfer(Side side, bool is_write, unsigned n, std::uint32_t address, std::span<std::uint8_t> buffer) {
    const std::uint32_t base = sm_base(n);
    const std::uint8_t control = memory_[base + reg::sm_control];
    const bool ecat_writes = (control & reg::sm_direction_mask) == reg::sm_direction_ecat_writes;
    const bool writer = (side == Side::ecat) == ecat_writes;
    const std::uint32_t start = sm_start(n), length = sm_length(n);
    const bool first_byte = address == start;
    const bool last_byte = address + buffer.size() == start + length;
    SmState& sm = sms_[n];
    // An access that completes one side's part wakes the other side: the AL event for the PDI,
    // the ECAT event for the master. The PDI's access to the buffer clears its event.
    const auto completed = [&] {
        if (side == Side::ecat)
            set_al_event(reg::al_event_sm(n));
        else if (n < 8)
            set_ecat_event(reg::ecat_event_sm(n));
    };
    if (side == Side::pdi) clear_al_event(reg::al_event_sm(n));

    if ((control & reg::sm_mode_mask) == reg::sm_mode_mailbox) {
        if (is_write)
            std::memcpy(memory_.data() + address, buffer.data(), buffer.size());
        else
            std::memcpy(buffer.data(), memory_.data() + address, buffer.size());
        if (is_write && writer && last_byte) {
            sm.full = true;
            completed();
        } else if (!is_write && !writer && last_byte) {
            sm.full = false;
            completed();
        }
        sm_refresh_status(n);
        return;
    }

    const std::uint32_t offset = address - start;
    if (is_write) {  // only the writer gets here (sm_accepts)
        if (sm.writing < 0 || first_byte) {
            std::int8_t free_buffer = 0;
            while (free_buffer == sm.newest || free_buffer == sm.reading) ++free_buffer;
            sm.writing = free_buffer;
        }
        std::memcpy(memory_.data() + start + length * static_cast<std::uint32_t>(sm.writing) + offset, buffer.data(),
                    buffer.size());
        if (last_byte) {
            sm.newest = sm.writing;
            sm.writing = -1;
            completed();
        }
    } else if (writer) {
        const std::uint32_t shown = sm.newest < 0 ? 0 : static_cast<std::uint32_t>(sm.newest);
        std::memcpy(buffer.data(), memory_.data() + start + length * shown + offset, buffer.size());
    } else {
        if (sm.reading < 0 || first_byte) sm.reading = sm.newest < 0 ? std::int8_t{0} : sm.newest;
        std::memcpy(buffer.data(), memory_.data() + start + length * static_cast<std::uint32_t>(sm.reading) + offset,
                    buffer.size());
        if (last_byte) {
            sm.reading = -1;
            completed();
        }
    }
    sm_refresh_status(n);
}

void Esc::sm_reset(unsigned n) {
    SmState& sm = sms_[n];
    sm.full = false;
    sm.newest = sm.reading = sm.writing = -1;
    sm_refresh_status(n);
}

void Esc::sm_refresh_status(unsigned n) {
    const std::uint32_t base = sm_base(n);
    const SmState& sm = sms_[n];
    std::uint8_t status = 0;
    if ((memory_[base + reg::sm_control] & reg::sm_mode_mask) == reg::sm_mode_mailbox) {
        if (sm.full) status |= reg::sm_status_mailbox_full | reg::sm_status_write_event;
    } else {
        status |= static_cast<std::uint8_t>((sm.newest < 0 ? 3 : sm.newest) << reg::sm_status_buffer_shift);
        if (sm.newest >= 0) status |= reg::sm_status_write_event;
        if (sm.reading >= 0) status |= reg::sm_status_read_open;
        if (sm.writing >= 0) status |= reg::sm_status_write_open;
    }
    memory_[base + reg::sm_status] = status;
}

// The master wrote an SM's activate register: enabling or disabling restarts the SM's buffers;
// any change (also a repeat request, bit 1) is an SM-activation event for the PDI.
void Esc::sm_activate_written(unsigned n) {
    const std::uint8_t now = memory_[sm_base(n) + reg::sm_activate];
    SmState& sm = sms_[n];
    if (now == sm.activate) return;
    if ((now ^ sm.activate) & reg::sm_activate_enable) sm_reset(n);
    sm.activate = now;
    sm_activation_unread_ |= 1u << n;
    set_al_event(reg::al_event_sm_activation);
}

}  // namespace esi::esc
