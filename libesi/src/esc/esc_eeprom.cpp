// The SII EEPROM as the ESC presents it (ESC datasheet section II 0x0500..0x050F; ETG.2010):
// the configuration area loaded at power-on, and the read/write/reload commands a master issues.
// Commands complete at once (never busy); writes change the image in memory only.

#include <algorithm>

#include "esi/config_crc.hpp"
#include "esi/esc/esc.hpp"
#include "esi/ethercat/registers.hpp"

namespace esi::esc {

namespace reg = ethercat::reg;

void Esc::load_eeprom() {
    // Bytes past the image read as an erased EEPROM (0xFF): a truncated image fails the
    // checksum as a real, partly programmed EEPROM would.
    std::uint8_t area[16];
    for (std::size_t i = 0; i < sizeof area; ++i) area[i] = i < eeprom_.size() ? eeprom_[i] : 0xFF;
    std::uint16_t control = reg::eeprom_read_8_bytes | reg::eeprom_two_address_bytes;
    eeprom_loaded_ = config_crc(std::span<const std::uint8_t>(area, 14)) == area[14];
    if (eeprom_loaded_) {
        memory_[reg::pdi_control] = area[0];
        memory_[reg::esc_configuration] = area[1];
        memory_[reg::pdi_configuration] = area[2];
        memory_[reg::pdi_configuration + 1] = area[3];
        memory_[reg::dc_sync_pulse_length] = area[4];
        memory_[reg::dc_sync_pulse_length + 1] = area[5];
        memory_[reg::pdi_configuration_ext] = area[6];
        memory_[reg::pdi_configuration_ext + 1] = area[7];
        memory_[reg::station_alias] = area[8];
        memory_[reg::station_alias + 1] = area[9];
    } else {
        for (const std::uint16_t a : {reg::pdi_control, reg::esc_configuration, reg::pdi_configuration,
                                      static_cast<std::uint16_t>(reg::pdi_configuration + 1), reg::pdi_configuration_ext,
                                      static_cast<std::uint16_t>(reg::pdi_configuration_ext + 1)})
            memory_[a] = 0;
        control |= reg::eeprom_checksum_error | reg::eeprom_not_loaded;
    }
    store16(reg::eeprom_control, control);
    refresh_dl_status();
}

void Esc::eeprom_command() {
    std::uint16_t control = peek16(reg::eeprom_control);
    const std::uint16_t command = control & reg::eeprom_command_mask;
    // Writing a command (NOP included) clears the previous command's error bits.
    control &= static_cast<std::uint16_t>(~(reg::eeprom_ack_error | reg::eeprom_write_error));
    const std::uint32_t word = peek32(reg::eeprom_address);
    if (command == reg::eeprom_command_read) {
        for (std::uint32_t i = 0; i < 8; ++i) {
            const std::uint64_t at = static_cast<std::uint64_t>(word) * 2 + i;
            memory_[reg::eeprom_data + i] = at < eeprom_.size() ? eeprom_[at] : 0xFF;
        }
    } else if (command == reg::eeprom_command_write) {
        const std::uint64_t at = static_cast<std::uint64_t>(word) * 2;
        if (!(control & reg::eeprom_write_enable)) {
            control |= reg::eeprom_write_error;
        } else if (at + 2 > 0x20000) {  // past the largest EEPROM the address bytes reach
            control |= reg::eeprom_ack_error;
        } else {
            if (eeprom_.size() < at + 2) eeprom_.resize(static_cast<std::size_t>(at + 2), 0xFF);
            eeprom_[at] = memory_[reg::eeprom_data];
            eeprom_[at + 1] = memory_[reg::eeprom_data + 1];
        }
    } else if (command == reg::eeprom_command_reload) {
        load_eeprom();
        control = static_cast<std::uint16_t>((control & ~(reg::eeprom_checksum_error | reg::eeprom_not_loaded)) |
                                             (peek16(reg::eeprom_control) & (reg::eeprom_checksum_error | reg::eeprom_not_loaded)));
    } else if (command != 0) {
        control |= reg::eeprom_ack_error;  // more than one command bit: not a command
    }
    control &= static_cast<std::uint16_t>(~(reg::eeprom_command_mask | reg::eeprom_write_enable));
    store16(reg::eeprom_control, control);
}

}  // namespace esi::esc
