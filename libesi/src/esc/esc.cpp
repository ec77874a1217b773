// The ESC's address space: which bytes each side may write, and the side effects of register
// accesses (ESC datasheet section II, the register descriptions' ECAT/PDI access columns).

#include "esi/esc/esc.hpp"

#include <algorithm>
#include <cstring>

#include "esi/ethercat/registers.hpp"

namespace esi::esc {

namespace reg = ethercat::reg;

namespace {

constexpr std::uint32_t address_space = 0x10000;

[[nodiscard]] bool touches(std::uint32_t first, std::uint32_t end, std::uint32_t reg, std::uint32_t size = 1) {
    return first < reg + size && reg < end;
}

}  // namespace

Esc::Esc(std::vector<std::uint8_t> eeprom, const EscConfig& config)
    : config_(config), memory_(address_space, 0), eeprom_(std::move(eeprom)) {
    config_.fmmus = std::min<std::uint8_t>(config_.fmmus, 16);
    config_.sync_managers = std::min<std::uint8_t>(config_.sync_managers, 16);
    config_.ram_kib = std::min<std::uint8_t>(config_.ram_kib, 60);
    sms_.resize(config_.sync_managers);
    memory_[reg::type] = config_.type;
    memory_[reg::revision] = config_.revision;
    store16(reg::build, config_.build);
    memory_[reg::fmmus_supported] = config_.fmmus;
    memory_[reg::sms_supported] = config_.sync_managers;
    memory_[reg::ram_size] = config_.ram_kib;
    memory_[reg::port_descriptor] = config_.port_descriptor;
    store16(reg::features, config_.features);
    memory_[reg::al_status] = 0x01;  // INIT
    store16(reg::ecat_event_mask, 0x0000);
    store32(reg::al_event_mask, 0xFFFFFFFF);  // the reset value: every event reaches the IRQ
    store16(reg::watchdog_divider, 0x09C2);   // 100 us with a 25 MHz clock
    store16(reg::watchdog_time_pdi, 0x03E8);  // 1000 x 100 us: 100 ms
    store16(reg::watchdog_time_process_data, 0x03E8);
    memory_[reg::watchdog_status_process_data] = 0x01;  // active or disabled; not expired
    load_eeprom();
}

bool Esc::pdi_active() const { return eeprom_loaded_ && memory_[reg::pdi_control] != 0; }

std::uint16_t Esc::peek16(std::uint16_t address) const {
    std::uint8_t b[2]{};
    peek(address, b);
    return static_cast<std::uint16_t>(b[0] | b[1] << 8);
}

std::uint32_t Esc::peek32(std::uint16_t address) const {
    std::uint8_t b[4]{};
    peek(address, b);
    return static_cast<std::uint32_t>(b[0] | b[1] << 8 | b[2] << 16) | static_cast<std::uint32_t>(b[3]) << 24;
}

std::uint64_t Esc::peek64(std::uint32_t address) const {
    std::uint64_t value = 0;
    for (unsigned i = 0; i < 8 && address + i < address_space; ++i)
        value |= static_cast<std::uint64_t>(memory_[address + i]) << (8 * i);
    return value;
}

void Esc::peek(std::uint16_t address, std::span<std::uint8_t> out) const {
    const std::size_t n = std::min<std::size_t>(out.size(), address_space - address);
    std::memcpy(out.data(), memory_.data() + address, n);
    std::fill(out.begin() + static_cast<std::ptrdiff_t>(n), out.end(), std::uint8_t{0});
}

void Esc::store16(std::uint32_t address, std::uint16_t value) {
    memory_[address] = static_cast<std::uint8_t>(value);
    memory_[address + 1] = static_cast<std::uint8_t>(value >> 8);
}

void Esc::store32(std::uint32_t address, std::uint32_t value) {
    for (unsigned i = 0; i < 4; ++i) memory_[address + i] = static_cast<std::uint8_t>(value >> (8 * i));
}

void Esc::store64(std::uint32_t address, std::uint64_t value) {
    for (unsigned i = 0; i < 8; ++i) memory_[address + i] = static_cast<std::uint8_t>(value >> (8 * i));
}

std::uint32_t Esc::al_event() const { return peek32(reg::al_event_request) & peek32(reg::al_event_mask); }

void Esc::set_al_event(std::uint32_t bits) { store32(reg::al_event_request, peek32(reg::al_event_request) | bits); }
void Esc::clear_al_event(std::uint32_t bits) { store32(reg::al_event_request, peek32(reg::al_event_request) & ~bits); }
void Esc::set_ecat_event(std::uint16_t bits) {
    store16(reg::ecat_event_request, static_cast<std::uint16_t>(peek16(reg::ecat_event_request) | bits));
}
void Esc::clear_ecat_event(std::uint16_t bits) {
    store16(reg::ecat_event_request, static_cast<std::uint16_t>(peek16(reg::ecat_event_request) & ~bits));
}

// The bits a side may change in a register byte. SyncManager configuration is writable by ECAT
// only while the SM is disabled, as on a real ESC (so a master cannot move a buffer under the
// PDI's feet).
std::uint8_t Esc::write_mask(Side side, std::uint32_t a) const {
    const std::uint32_t fmmu_end = reg::fmmu0 + reg::fmmu_stride * config_.fmmus;
    const std::uint32_t sm_end = reg::sm0 + reg::sm_stride * config_.sync_managers;
    if (side == Side::ecat) {
        if (a >= reg::fmmu0 && a < fmmu_end) return (a - reg::fmmu0) % reg::fmmu_stride < 13 ? 0xFF : 0x00;
        if (a >= reg::sm0 && a < sm_end) {
            const unsigned n = (a - reg::sm0) / reg::sm_stride, offset = (a - reg::sm0) % reg::sm_stride;
            if (offset < reg::sm_status) return (memory_[reg::sm0 + reg::sm_stride * n + reg::sm_activate] & 1) ? 0 : 0xFF;
            if (offset == reg::sm_activate) return 0xC3;
            return 0x00;
        }
        switch (a) {
        case reg::station_address: case reg::station_address + 1:
        case reg::dl_control: case reg::dl_control + 1: case reg::dl_control + 2: case reg::dl_control + 3:
        case reg::physical_rw_offset: case reg::physical_rw_offset + 1:
        case reg::al_control: case reg::al_control + 1:
        case reg::ecat_event_mask: case reg::ecat_event_mask + 1:
        case reg::watchdog_divider: case reg::watchdog_divider + 1:
        case reg::watchdog_time_pdi: case reg::watchdog_time_pdi + 1:
        case reg::watchdog_time_process_data: case reg::watchdog_time_process_data + 1:
        case reg::eeprom_configuration:
        case reg::eeprom_address: case reg::eeprom_address + 1: case reg::eeprom_address + 2: case reg::eeprom_address + 3:
        case reg::eeprom_data: case reg::eeprom_data + 1:
        case reg::mii_management: case reg::mii_management + 1: case reg::mii_management + 2:
        case reg::mii_management + 3: case reg::mii_management + 4: case reg::mii_management + 5:
        case reg::dc_cyclic_unit_control: case reg::dc_sync_activation:
            return 0xFF;
        case reg::eeprom_control: return 0x01;       // write enable
        case reg::eeprom_control + 1: return 0x07;   // command
        default: break;
        }
        if (a >= reg::dc_system_time_offset && a < reg::dc_system_time_difference) return 0xFF;  // offset, delay
        if (a >= reg::dc_speed_counter_start && a < reg::dc_speed_counter_start + 6) return 0xFF;
        if (a >= reg::dc_start_time && a < reg::dc_start_time + 8) return 0xFF;
        if (a >= reg::dc_sync0_cycle && a < reg::dc_sync0_cycle + 10) return 0xFF;  // cycles, latch control
        return 0x00;
    }
    if (a >= reg::sm0 && a < sm_end && (a - reg::sm0) % reg::sm_stride == reg::sm_pdi_control) return 0x03;
    // With device emulation the ESC itself drives AL status from AL control; the PDI cannot
    // write AL status or its code (ESC datasheet section II, 0x0130 and 0x0141).
    const bool emulation = memory_[reg::esc_configuration] & reg::esc_configuration_device_emulation;
    if (a >= reg::al_status && a < reg::al_status + 2) return emulation ? 0x00 : 0xFF;
    if (a >= reg::al_status_code && a < reg::al_status_code + 2) return emulation ? 0x00 : 0xFF;
    if (a >= reg::al_event_mask && a < reg::al_event_mask + 4) return 0xFF;
    if (a >= reg::station_alias && a < reg::station_alias + 2) return 0xFF;
    return 0x00;
}

void Esc::register_read(Side side, std::uint32_t address, std::span<std::uint8_t> out) {
    const std::uint32_t end = address + static_cast<std::uint32_t>(out.size());
    if (touches(address, end, reg::dl_status, 2)) refresh_dl_status();
    std::memcpy(out.data(), memory_.data() + address, out.size());
    if (side == Side::ecat) {
        if (touches(address, end, reg::al_status, 2)) clear_ecat_event(reg::ecat_event_al_status);
        return;
    }
    if (touches(address, end, reg::al_control, 2)) clear_al_event(reg::al_event_al_control);
    if (touches(address, end, reg::watchdog_status_process_data, 2)) watchdog_status_read_by_pdi();
    for (unsigned n = 0; n < config_.sync_managers; ++n)
        if (touches(address, end, reg::sm0 + reg::sm_stride * n + reg::sm_activate)) sm_activation_unread_ &= ~(1u << n);
    if (sm_activation_unread_ == 0) clear_al_event(reg::al_event_sm_activation);
}

void Esc::register_write(Side side, std::uint32_t address, std::span<const std::uint8_t> in) {
    // Byte by byte in address order, as the frame passes: a write that disables an SM and sets
    // up the next one in one datagram works as it does on a real ESC.
    for (std::size_t i = 0; i < in.size(); ++i) {
        const std::uint32_t a = address + static_cast<std::uint32_t>(i);
        const std::uint8_t mask = write_mask(side, a);
        memory_[a] = static_cast<std::uint8_t>((memory_[a] & ~mask) | (in[i] & mask));
    }
    const std::uint32_t end = address + static_cast<std::uint32_t>(in.size());
    if (side == Side::ecat)
        after_ecat_write(address, end);
    else
        after_pdi_write(address, end);
}

void Esc::after_ecat_write(std::uint32_t first, std::uint32_t end) {
    if (touches(first, end, reg::al_control, 2)) {
        set_al_event(reg::al_event_al_control);
        // Device emulation (simple terminals without a microcontroller): the ESC itself copies
        // the requested state into AL status. The error-acknowledge bit is not copied: there is
        // no error to indicate.
        if (memory_[reg::esc_configuration] & reg::esc_configuration_device_emulation) {
            memory_[reg::al_status] = memory_[reg::al_control] & 0x0F;
            set_ecat_event(reg::ecat_event_al_status);
        }
    }
    if (touches(first, end, reg::eeprom_control, 2)) eeprom_command();
    // The watchdog expiry counters are cleared with the RX error counters (0x0300..0x030B).
    if (touches(first, end, reg::error_counters, 12)) {
        memory_[reg::watchdog_counter_process_data] = 0;
        memory_[reg::watchdog_counter_pdi] = 0;
    }
    for (unsigned n = 0; n < config_.sync_managers; ++n) {
        const std::uint32_t base = reg::sm0 + reg::sm_stride * n;
        if (touches(first, end, base, reg::sm_status) && !(memory_[base + reg::sm_activate] & 1)) sm_reset(n);
        if (touches(first, end, base + reg::sm_activate)) sm_activate_written(n);
    }
    if (touches(first, end, reg::dc_receive_time_port0)) {
        // A write to 0x0900 latches the receive times of this frame (ETG.1000.4 DC, "propagation
        // delay measurement"): port 0 when it arrived, port 1 when it comes back.
        store32(reg::dc_receive_time_port0, static_cast<std::uint32_t>(pass_.port0_time_ns));
        store32(reg::dc_receive_time_port0 + 4, pass_.port1_link ? static_cast<std::uint32_t>(pass_.port1_time_ns) : 0);
        store32(reg::dc_receive_time_port0 + 8, 0);
        store32(reg::dc_receive_time_port0 + 12, 0);
        store64(reg::dc_receive_time_pu, pass_.port0_time_ns);
    }
    if (touches(first, end, reg::dc_system_time, 4)) {
        // The time control loop's input: the difference to the written (reference) time. The
        // clocks are one idealised clock, so nothing is corrected.
        const auto written = static_cast<std::uint32_t>(peek64(reg::dc_system_time));
        refresh_system_time();
        const auto own = static_cast<std::uint32_t>(peek64(reg::dc_system_time));
        const std::uint32_t diff = own >= written ? own - written : (written - own) | 0x80000000u;
        store32(reg::dc_system_time_difference, diff);
    }
    if (touches(first, end, reg::dc_system_time_offset, 8)) refresh_system_time();
    if (touches(first, end, reg::dc_sync_activation)) {
        const std::uint8_t act = memory_[reg::dc_sync_activation];
        memory_[reg::dc_activation_status] = (act & 1) ? static_cast<std::uint8_t>((act >> 1) & 0x03) : 0;
    }
}

void Esc::after_pdi_write(std::uint32_t first, std::uint32_t end) {
    if (touches(first, end, reg::al_status, 2)) set_ecat_event(reg::ecat_event_al_status);
    for (unsigned n = 0; n < config_.sync_managers; ++n) {
        const std::uint32_t base = reg::sm0 + reg::sm_stride * n;
        if (touches(first, end, base + reg::sm_pdi_control) &&
            ((memory_[base + reg::sm_pdi_control] ^ sms_[n].activate) & reg::sm_pdi_deactivate) != 0)
            sm_refresh_status(n);
    }
}

void Esc::refresh_dl_status() {
    std::uint16_t status = 0;
    if (eeprom_loaded_) status |= reg::dl_status_pdi_operational;
    status |= 1u << 4;  // port 0 has a link: frames reach this ESC through it
    status |= 1u << 9;  // port 0: communication established, loop open
    if (pass_.port1_link) status |= (1u << 5) | (1u << 11);
    if (!forwards_to_port1()) status |= 1u << 10;  // port 1 loop closed
    // Ports 2 and 3 are not connected: their loops are closed.
    status |= (1u << 12) | (1u << 14);
    store16(reg::dl_status, status);
}

void Esc::refresh_system_time() {
    store64(reg::dc_system_time, pass_.port0_time_ns + peek64(reg::dc_system_time_offset));
}

bool Esc::forwards_to_port1() const {
    const unsigned loop = (memory_[reg::dl_port] >> 2) & 0x03;  // 00 auto, 01 auto close, 10 open, 11 closed
    if (loop == 0x03) return false;
    return pass_.port1_link;
}

bool Esc::port0_closed() const { return (memory_[reg::dl_port] & 0x03) == 0x03; }

void Esc::plain_access(Side side, bool is_write, std::uint32_t address, std::span<std::uint8_t> buffer) {
    const std::uint32_t ram_end = reg::process_ram + 1024u * config_.ram_kib;
    if (address < reg::process_ram) {
        if (is_write)
            register_write(side, address, buffer);
        else
            register_read(side, address, buffer);
        return;
    }
    if (address >= ram_end) {
        if (!is_write) std::fill(buffer.begin(), buffer.end(), std::uint8_t{0});
        return;
    }
    if (is_write)
        std::memcpy(memory_.data() + address, buffer.data(), buffer.size());
    else
        std::memcpy(buffer.data(), memory_.data() + address, buffer.size());
}

// One access of either side: the SyncManagers whose windows it touches decide whether it is
// accepted (all or nothing, so a refused mailbox write leaves memory untouched), then each part
// goes to its SM or to plain registers/RAM.
bool Esc::access(Side side, bool is_write, std::uint16_t address, std::span<std::uint8_t> buffer) {
    const std::uint32_t first = address;
    const std::uint32_t end = std::min<std::uint32_t>(first + static_cast<std::uint32_t>(buffer.size()), address_space);
    if (end <= first) return true;
    std::uint32_t hits = 0;
    for (unsigned n = 0; n < config_.sync_managers; ++n) {
        if (!sm_enabled(n)) continue;
        const std::uint32_t s = sm_start(n), e = s + sm_length(n);
        if (s < end && first < e) {
            if (!sm_accepts(side, is_write, n)) return false;
            hits |= 1u << n;
        }
    }
    std::uint32_t pos = first;
    while (pos < end) {
        std::uint32_t seg_end = end;
        bool done = false;
        for (unsigned n = 0; n < config_.sync_managers && !done; ++n) {
            if (!(hits & (1u << n))) continue;
            const std::uint32_t s = sm_start(n), e = s + sm_length(n);
            if (pos >= s && pos < e) {
                seg_end = std::min(e, end);
                sm_transfer(side, is_write, n, pos, buffer.subspan(pos - first, seg_end - pos));
                done = true;
            } else if (s > pos) {
                seg_end = std::min(seg_end, s);
            }
        }
        if (!done) plain_access(side, is_write, pos, buffer.subspan(pos - first, seg_end - pos));
        pos = seg_end;
    }
    if (side == Side::ecat && is_write && hits) watchdog_triggered_by(hits);
    return true;
}

void Esc::read(std::uint16_t address, std::span<std::uint8_t> out) { access(Side::pdi, false, address, out); }

void Esc::write(std::uint16_t address, std::span<const std::uint8_t> in) {
    // access() takes a mutable span for both directions; with is_write it only reads the buffer,
    // so the firmware's data is passed as it is (no copy per access).
    access(Side::pdi, true, address, std::span<std::uint8_t>(const_cast<std::uint8_t*>(in.data()), in.size()));
}

}  // namespace esi::esc
