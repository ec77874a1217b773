#pragma once
// The mailbox (ETG.1000.4 5.6, ETG.1000.6 5.2-5.6): its header, the protocol types, the error
// reply's details, CoE's services and the SDO abort codes. Named once here for the emulated
// slave's mailbox and CoE server, the master's client and the tools that print them.

#include <cstdint>
#include <string_view>

namespace esi::ethercat {

// The 6-byte mailbox header: length (2), address (2), channel and priority (1), type and
// counter (1: type in bits 0..3, counter 1..7 in bits 4..6).
inline constexpr std::size_t mailbox_header_bytes = 6;

namespace mailbox_type {
inline constexpr std::uint8_t error = 0x00;
inline constexpr std::uint8_t aoe = 0x01;
inline constexpr std::uint8_t eoe = 0x02;
inline constexpr std::uint8_t coe = 0x03;
inline constexpr std::uint8_t foe = 0x04;
inline constexpr std::uint8_t soe = 0x05;
inline constexpr std::uint8_t voe = 0x0F;
}  // namespace mailbox_type

// The detail of a mailbox error reply (type 0; ETG.1000.4 Table "Mailbox error reply").
namespace mailbox_error {
inline constexpr std::uint16_t syntax = 0x0001;
inline constexpr std::uint16_t unsupported_protocol = 0x0002;
inline constexpr std::uint16_t invalid_channel = 0x0003;
inline constexpr std::uint16_t service_not_supported = 0x0004;
inline constexpr std::uint16_t invalid_header = 0x0005;
inline constexpr std::uint16_t size_too_short = 0x0006;
inline constexpr std::uint16_t no_more_memory = 0x0007;
inline constexpr std::uint16_t invalid_size = 0x0008;
}  // namespace mailbox_error
[[nodiscard]] std::string_view mailbox_error_text(std::uint16_t detail);

// The CoE header: number (bits 0..8) and service (bits 12..15) (ETG.1000.6 Table 29).
inline constexpr std::size_t coe_header_bytes = 2;
namespace coe_service {
inline constexpr std::uint8_t emergency = 1;
inline constexpr std::uint8_t sdo_request = 2;
inline constexpr std::uint8_t sdo_response = 3;
inline constexpr std::uint8_t tx_pdo = 4;
inline constexpr std::uint8_t rx_pdo = 5;
inline constexpr std::uint8_t tx_pdo_remote_request = 6;
inline constexpr std::uint8_t rx_pdo_remote_request = 7;
inline constexpr std::uint8_t sdo_information = 8;
}  // namespace coe_service

// The SDO command byte (ETG.1000.6 5.6.2): the command specifier in bits 5..7 and its flags.
namespace sdo_command {
inline constexpr std::uint8_t download_segment = 0;
inline constexpr std::uint8_t initiate_download = 1;
inline constexpr std::uint8_t initiate_upload = 2;
inline constexpr std::uint8_t upload_segment = 3;
inline constexpr std::uint8_t abort = 4;  // the abort transfer, sent as an SDO request (5.6.2.7)
[[nodiscard]] constexpr std::uint8_t specifier(std::uint8_t command) { return static_cast<std::uint8_t>(command >> 5); }
[[nodiscard]] constexpr std::uint8_t byte_of(std::uint8_t specifier) { return static_cast<std::uint8_t>(specifier << 5); }
// The server's answers (SDO responses) have specifiers of their own.
inline constexpr std::uint8_t response_upload_segment = 0;
inline constexpr std::uint8_t response_download_segment = 1;
inline constexpr std::uint8_t response_initiate_upload = 2;
inline constexpr std::uint8_t response_initiate_download = 3;
inline constexpr std::uint8_t size_indicated = 0x01;
inline constexpr std::uint8_t expedited = 0x02;
inline constexpr std::uint8_t complete_access = 0x10;
inline constexpr std::uint8_t toggle = 0x10;  // segments
}  // namespace sdo_command
inline constexpr std::uint8_t sdo_abort_command = sdo_command::abort << 5;

// SDO Information (ETG.1000.6 5.6.3): the opcode in bits 0..6 of the first header byte, bit 7
// "incomplete" (more fragments follow).
namespace sdo_info_opcode {
inline constexpr std::uint8_t get_od_list = 0x01;
inline constexpr std::uint8_t od_list_response = 0x02;
inline constexpr std::uint8_t get_object_description = 0x03;
inline constexpr std::uint8_t object_description_response = 0x04;
inline constexpr std::uint8_t get_entry_description = 0x05;
inline constexpr std::uint8_t entry_description_response = 0x06;
inline constexpr std::uint8_t error = 0x07;
inline constexpr std::uint8_t incomplete = 0x80;
}  // namespace sdo_info_opcode

// SDO abort codes (ETG.1000.6 Table 41, after CiA 301).
namespace sdo_abort {
inline constexpr std::uint32_t none = 0;
inline constexpr std::uint32_t toggle_bit = 0x05030000;
inline constexpr std::uint32_t timeout = 0x05040000;
inline constexpr std::uint32_t command_specifier = 0x05040001;
inline constexpr std::uint32_t out_of_memory = 0x05040005;
inline constexpr std::uint32_t unsupported_access = 0x06010000;
inline constexpr std::uint32_t write_only = 0x06010001;
inline constexpr std::uint32_t read_only = 0x06010002;
inline constexpr std::uint32_t subindex_0_not_zero = 0x06010003;  // SI0 must be 0 before writing the entries
inline constexpr std::uint32_t no_complete_access = 0x06010004;
inline constexpr std::uint32_t object_too_long = 0x06010005;
inline constexpr std::uint32_t mapped_to_rx_pdo = 0x06010006;
inline constexpr std::uint32_t object_missing = 0x06020000;
inline constexpr std::uint32_t not_mappable = 0x06040041;
inline constexpr std::uint32_t pdo_length_exceeded = 0x06040042;
inline constexpr std::uint32_t parameter_incompatible = 0x06040043;
inline constexpr std::uint32_t device_incompatible = 0x06040047;
inline constexpr std::uint32_t hardware_error = 0x06060000;
inline constexpr std::uint32_t length_mismatch = 0x06070010;
inline constexpr std::uint32_t length_too_long = 0x06070012;
inline constexpr std::uint32_t length_too_short = 0x06070013;
inline constexpr std::uint32_t subindex_missing = 0x06090011;
inline constexpr std::uint32_t value_range = 0x06090030;
inline constexpr std::uint32_t value_too_high = 0x06090031;
inline constexpr std::uint32_t value_too_low = 0x06090032;
inline constexpr std::uint32_t maximum_below_minimum = 0x06090036;
inline constexpr std::uint32_t general = 0x08000000;
inline constexpr std::uint32_t cannot_store = 0x08000020;
inline constexpr std::uint32_t cannot_store_local_control = 0x08000021;
inline constexpr std::uint32_t device_state = 0x08000022;
inline constexpr std::uint32_t no_dictionary = 0x08000023;
}  // namespace sdo_abort
// The text ETG.1000.6 Table 41 gives a code; "unknown abort code" for any other.
[[nodiscard]] std::string_view sdo_abort_text(std::uint32_t code);

}  // namespace esi::ethercat
