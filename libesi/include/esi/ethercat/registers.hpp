#pragma once
// ESC register addresses and bits (ESC datasheet section II, register map; ETG.1000.4 for the DL
// registers). Named once here, in the protocol layer, so that the emulated ESC, the slave stacks
// on it, the master and the network writers agree on them.

#include <cstdint>

namespace esi::ethercat::reg {

inline constexpr std::uint16_t type = 0x0000;
inline constexpr std::uint16_t revision = 0x0001;
inline constexpr std::uint16_t build = 0x0002;
inline constexpr std::uint16_t fmmus_supported = 0x0004;
inline constexpr std::uint16_t sms_supported = 0x0005;
inline constexpr std::uint16_t ram_size = 0x0006;  // KiB
inline constexpr std::uint16_t port_descriptor = 0x0007;
inline constexpr std::uint16_t features = 0x0008;
inline constexpr std::uint16_t station_address = 0x0010;
inline constexpr std::uint16_t station_alias = 0x0012;
inline constexpr std::uint16_t dl_control = 0x0100;
inline constexpr std::uint16_t dl_port = 0x0101;   // loop control, 2 bits per port
inline constexpr std::uint16_t dl_alias = 0x0103;  // bit 0: station alias enable (DL control bit 24)
inline constexpr std::uint16_t physical_rw_offset = 0x0108;
inline constexpr std::uint16_t dl_status = 0x0110;
inline constexpr std::uint16_t al_control = 0x0120;
inline constexpr std::uint16_t al_status = 0x0130;
inline constexpr std::uint16_t al_status_code = 0x0134;
inline constexpr std::uint16_t pdi_control = 0x0140;
inline constexpr std::uint16_t esc_configuration = 0x0141;
inline constexpr std::uint16_t pdi_configuration = 0x0150;
inline constexpr std::uint16_t pdi_configuration_ext = 0x0152;
inline constexpr std::uint16_t ecat_event_mask = 0x0200;
inline constexpr std::uint16_t al_event_mask = 0x0204;
inline constexpr std::uint16_t ecat_event_request = 0x0210;
inline constexpr std::uint16_t al_event_request = 0x0220;
inline constexpr std::uint16_t error_counters = 0x0300;  // 0x0300..0x0313
inline constexpr std::uint16_t watchdog_divider = 0x0400;
inline constexpr std::uint16_t watchdog_time_pdi = 0x0410;
inline constexpr std::uint16_t watchdog_time_process_data = 0x0420;
inline constexpr std::uint16_t watchdog_status_process_data = 0x0440;  // bit 0: 1 active or disabled, 0 expired
inline constexpr std::uint16_t watchdog_counter_process_data = 0x0442;
inline constexpr std::uint16_t watchdog_counter_pdi = 0x0443;
inline constexpr std::uint16_t eeprom_configuration = 0x0500;
inline constexpr std::uint16_t eeprom_pdi_state = 0x0501;
inline constexpr std::uint16_t eeprom_control = 0x0502;
inline constexpr std::uint16_t eeprom_address = 0x0504;
inline constexpr std::uint16_t eeprom_data = 0x0508;
inline constexpr std::uint16_t mii_management = 0x0510;  // 0x0510..0x0515: control/status, PHY address, register
inline constexpr std::uint16_t fmmu0 = 0x0600;  // 16 bytes per FMMU
inline constexpr std::uint16_t sm0 = 0x0800;    // 8 bytes per SyncManager
inline constexpr std::uint16_t dc_receive_time_port0 = 0x0900;  // 0x0900/04/08/0C: ports 0..3
inline constexpr std::uint16_t dc_system_time = 0x0910;
inline constexpr std::uint16_t dc_receive_time_pu = 0x0918;
inline constexpr std::uint16_t dc_system_time_offset = 0x0920;
inline constexpr std::uint16_t dc_system_time_delay = 0x0928;
inline constexpr std::uint16_t dc_system_time_difference = 0x092C;
inline constexpr std::uint16_t dc_speed_counter_start = 0x0930;
inline constexpr std::uint16_t dc_time_filter = 0x0934;
inline constexpr std::uint16_t dc_cyclic_unit_control = 0x0980;
inline constexpr std::uint16_t dc_sync_activation = 0x0981;
inline constexpr std::uint16_t dc_sync_pulse_length = 0x0982;
inline constexpr std::uint16_t dc_activation_status = 0x0984;
inline constexpr std::uint16_t dc_sync0_status = 0x098E;
inline constexpr std::uint16_t dc_sync1_status = 0x098F;
inline constexpr std::uint16_t dc_start_time = 0x0990;
inline constexpr std::uint16_t dc_sync0_cycle = 0x09A0;
inline constexpr std::uint16_t dc_sync1_cycle = 0x09A4;
inline constexpr std::uint16_t dc_latch0_control = 0x09A8;  // and 0x09A9, latch 1
inline constexpr std::uint16_t process_ram = 0x1000;

// SyncManager register offsets (from sm0 + 8 n).
inline constexpr std::uint16_t sm_start = 0, sm_length = 2, sm_control = 4, sm_status = 5, sm_activate = 6,
                               sm_pdi_control = 7;
inline constexpr std::uint16_t sm_stride = 8;
// SyncManager n's first register.
[[nodiscard]] constexpr std::uint16_t sm(std::uint32_t n) { return static_cast<std::uint16_t>(sm0 + sm_stride * n); }
inline constexpr std::uint8_t sm_control_watchdog_trigger = 0x40;
// FMMU register offsets (from fmmu0 + 16 n).
inline constexpr std::uint16_t fmmu_logical_start = 0, fmmu_length = 4, fmmu_logical_start_bit = 6,
                               fmmu_logical_stop_bit = 7, fmmu_physical_start = 8, fmmu_physical_start_bit = 10,
                               fmmu_type = 11, fmmu_activate = 12;
inline constexpr std::uint16_t fmmu_stride = 16;
// FMMU n's first register.
[[nodiscard]] constexpr std::uint16_t fmmu(std::uint32_t n) { return static_cast<std::uint16_t>(fmmu0 + fmmu_stride * n); }

// AL event request (0x0220) bits.
inline constexpr std::uint32_t al_event_al_control = 1u << 0;
inline constexpr std::uint32_t al_event_sync0 = 1u << 2;
inline constexpr std::uint32_t al_event_sync1 = 1u << 3;
inline constexpr std::uint32_t al_event_sm_activation = 1u << 4;
inline constexpr std::uint32_t al_event_eeprom = 1u << 5;
inline constexpr std::uint32_t al_event_watchdog_process_data = 1u << 6;
[[nodiscard]] constexpr std::uint32_t al_event_sm(unsigned n) { return 1u << (8 + n); }

// ECAT event request (0x0210) bits.
inline constexpr std::uint16_t ecat_event_dl_status = 1u << 2;
inline constexpr std::uint16_t ecat_event_al_status = 1u << 3;
[[nodiscard]] constexpr std::uint16_t ecat_event_sm(unsigned n) { return static_cast<std::uint16_t>(1u << (4 + n)); }

// DL status (0x0110) bits.
inline constexpr std::uint16_t dl_status_pdi_operational = 1u << 0;

// EEPROM control/status (0x0502) bits.
inline constexpr std::uint16_t eeprom_write_enable = 1u << 0;
inline constexpr std::uint16_t eeprom_read_8_bytes = 1u << 6;
inline constexpr std::uint16_t eeprom_two_address_bytes = 1u << 7;
inline constexpr std::uint16_t eeprom_command_mask = 7u << 8;
inline constexpr std::uint16_t eeprom_command_read = 1u << 8;
inline constexpr std::uint16_t eeprom_command_write = 2u << 8;
inline constexpr std::uint16_t eeprom_command_reload = 4u << 8;
inline constexpr std::uint16_t eeprom_checksum_error = 1u << 11;
inline constexpr std::uint16_t eeprom_not_loaded = 1u << 12;
inline constexpr std::uint16_t eeprom_ack_error = 1u << 13;
inline constexpr std::uint16_t eeprom_write_error = 1u << 14;
inline constexpr std::uint16_t eeprom_busy = 1u << 15;

// SyncManager control (+4), status (+5), activate (+6), PDI control (+7) bits.
inline constexpr std::uint8_t sm_mode_mask = 0x03, sm_mode_buffered = 0x00, sm_mode_mailbox = 0x02;
inline constexpr std::uint8_t sm_direction_mask = 0x0C, sm_direction_ecat_writes = 0x04;
inline constexpr std::uint8_t sm_status_write_event = 1u << 0, sm_status_read_event = 1u << 1,
                              sm_status_mailbox_full = 1u << 3, sm_status_buffer_shift = 4,
                              sm_status_read_open = 1u << 6, sm_status_write_open = 1u << 7;
inline constexpr std::uint8_t sm_activate_enable = 1u << 0, sm_activate_repeat = 1u << 1;
inline constexpr std::uint8_t sm_pdi_deactivate = 1u << 0, sm_pdi_repeat_ack = 1u << 1;

// ESC configuration (0x0141) bit 0: device emulation (AL status follows AL control).
inline constexpr std::uint8_t esc_configuration_device_emulation = 1u << 0;

}  // namespace esi::ethercat::reg
