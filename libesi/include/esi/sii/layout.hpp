#pragma once
// The SII EEPROM layout: word addresses of the fixed header, category codes and the sizes of
// the fixed-size category records. Sources: ETG.1000.6 Tables 16-23 and ETG.2010 Tables 2, 4,
// 12, 14; the Beckhoff ESC data
// sheet Section I, Table 37/38. Words are little-endian; "offset" always means a byte offset.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "esi/model/mailbox_protocol.hpp"

namespace esi::sii {

// Word addresses of the header (0x00-0x3F).
namespace word {
inline constexpr std::uint16_t pdi_control = 0x00;
inline constexpr std::uint16_t pdi_configuration = 0x01;
inline constexpr std::uint16_t sync_impulse_length = 0x02;
inline constexpr std::uint16_t pdi_configuration2 = 0x03;
inline constexpr std::uint16_t station_alias = 0x04;
inline constexpr std::uint16_t checksum = 0x07;
inline constexpr std::uint16_t vendor_id = 0x08;
inline constexpr std::uint16_t product_code = 0x0A;
inline constexpr std::uint16_t revision_no = 0x0C;
inline constexpr std::uint16_t serial_no = 0x0E;
inline constexpr std::uint16_t execution_delay = 0x10;
inline constexpr std::uint16_t port0_delay = 0x11;
inline constexpr std::uint16_t port1_delay = 0x12;
inline constexpr std::uint16_t bootstrap_receive_offset = 0x14;
inline constexpr std::uint16_t bootstrap_receive_size = 0x15;
inline constexpr std::uint16_t bootstrap_send_offset = 0x16;
inline constexpr std::uint16_t bootstrap_send_size = 0x17;
inline constexpr std::uint16_t standard_receive_offset = 0x18;
inline constexpr std::uint16_t standard_receive_size = 0x19;
inline constexpr std::uint16_t standard_send_offset = 0x1A;
inline constexpr std::uint16_t standard_send_size = 0x1B;
inline constexpr std::uint16_t mailbox_protocols = 0x1C;
inline constexpr std::uint16_t size = 0x3E;
inline constexpr std::uint16_t version = 0x3F;
inline constexpr std::uint16_t first_category = 0x40;
}  // namespace word

inline constexpr std::size_t header_bytes = 0x80;          // words 0x00-0x3F
inline constexpr std::size_t config_area_bytes = 14;       // words 0-6, covered by the CRC
inline constexpr std::size_t minimum_image_bytes = 0x82;   // IgH sii_write: 0x40 words + end marker
inline constexpr std::uint16_t crc_disabled_marker = 0x88A4;  // ESC data sheet: "never for production"
inline constexpr std::uint16_t end_marker = 0xFFFF;

// Word 0x3E holds the EEPROM size in KiBit minus one: bytes = (word + 1) * 128.
[[nodiscard]] constexpr std::uint64_t eeprom_bytes_from_size_word(std::uint16_t size_word) {
    return (static_cast<std::uint64_t>(size_word) + 1u) * 128u;
}

// Category type codes (ETG.1000.6 Table 19, ETG.2010 Table 1).
namespace category {
inline constexpr std::uint16_t nop = 0;
inline constexpr std::uint16_t strings = 10;
inline constexpr std::uint16_t data_types = 20;
inline constexpr std::uint16_t general = 30;
inline constexpr std::uint16_t fmmu = 40;
inline constexpr std::uint16_t sync_manager = 41;
inline constexpr std::uint16_t fmmu_ex = 42;
inline constexpr std::uint16_t sync_unit = 43;
inline constexpr std::uint16_t tx_pdo = 50;
inline constexpr std::uint16_t rx_pdo = 51;
inline constexpr std::uint16_t dc = 60;
inline constexpr std::uint16_t timeouts = 70;
inline constexpr std::uint16_t dictionary = 80;
inline constexpr std::uint16_t hardware = 90;
inline constexpr std::uint16_t vendor_information = 100;
inline constexpr std::uint16_t images = 110;
inline constexpr std::uint16_t end = 0xFFFF;
}  // namespace category

// "Strings", "General", "device specific", "vendor specific" ... for any code.
[[nodiscard]] std::string_view category_name(std::uint16_t type);

// A category's length word: at most 0xFFFF words of payload.
inline constexpr std::size_t max_category_words = 0xFFFF;

// Fixed record sizes in bytes.
inline constexpr std::size_t general_bytes = 32;         // IgH rejects any other size
inline constexpr std::size_t sync_manager_bytes = 8;
inline constexpr std::size_t pdo_header_bytes = 8;
inline constexpr std::size_t pdo_entry_bytes = 8;
inline constexpr std::size_t dc_op_mode_bytes = 24;      // ETG.2010 Table 12

// Word 0x1C bits (ETG.1000.6 Table 18).
namespace mailbox_protocol {
inline constexpr std::uint16_t aoe = sii_bit(MailboxProtocol::aoe);  // 0x01
inline constexpr std::uint16_t eoe = sii_bit(MailboxProtocol::eoe);  // 0x02
inline constexpr std::uint16_t coe = sii_bit(MailboxProtocol::coe);  // 0x04
inline constexpr std::uint16_t foe = sii_bit(MailboxProtocol::foe);  // 0x08
inline constexpr std::uint16_t soe = sii_bit(MailboxProtocol::soe);  // 0x10
inline constexpr std::uint16_t voe = sii_bit(MailboxProtocol::voe);  // 0x20
}  // namespace mailbox_protocol

// General category byte 5 (CoE details).
namespace coe_detail {
inline constexpr std::uint8_t sdo = 0x01;
inline constexpr std::uint8_t sdo_info = 0x02;
inline constexpr std::uint8_t pdo_assign = 0x04;
inline constexpr std::uint8_t pdo_configuration = 0x08;
inline constexpr std::uint8_t pdo_upload = 0x10;
inline constexpr std::uint8_t complete_access = 0x20;
}  // namespace coe_detail

// General category byte 11 (flags).
namespace general_flag {
inline constexpr std::uint8_t enable_safe_op = 0x01;
inline constexpr std::uint8_t enable_not_lrw = 0x02;
inline constexpr std::uint8_t mailbox_data_link_layer = 0x04;
inline constexpr std::uint8_t ident_al_status = 0x08;
inline constexpr std::uint8_t ident_physical_memory = 0x10;
}  // namespace general_flag

// Physical port nibbles of General bytes 16-17 (4 bits per port, port 0 in the low nibble).
namespace port_type {
inline constexpr std::uint8_t none = 0;
inline constexpr std::uint8_t mii = 1;
inline constexpr std::uint8_t reserved = 2;
inline constexpr std::uint8_t ebus = 3;
inline constexpr std::uint8_t fast_hot_connect = 4;
}  // namespace port_type

// FMMU category bytes (ETG.1000.6 Table 23). 0xFF is also "not used" (Beckhoff pads with it).
namespace fmmu_usage {
inline constexpr std::uint8_t unused = 0x00;
inline constexpr std::uint8_t outputs = 0x01;
inline constexpr std::uint8_t inputs = 0x02;
inline constexpr std::uint8_t sync_manager_status = 0x03;
inline constexpr std::uint8_t unused_ff = 0xFF;
}  // namespace fmmu_usage

// SyncM category: enable byte bits and type byte.
namespace sm_enable {
inline constexpr std::uint8_t enable = 0x01;
inline constexpr std::uint8_t fixed_content = 0x02;
inline constexpr std::uint8_t virtual_sm = 0x04;
inline constexpr std::uint8_t op_only = 0x08;
}  // namespace sm_enable
namespace sm_type {
inline constexpr std::uint8_t unused = 0;
inline constexpr std::uint8_t mailbox_out = 1;
inline constexpr std::uint8_t mailbox_in = 2;
inline constexpr std::uint8_t outputs = 3;
inline constexpr std::uint8_t inputs = 4;
}  // namespace sm_type

// TxPDO/RxPDO header flags (ETG.2010 Table 14).
namespace pdo_flag {
inline constexpr std::uint16_t mandatory = 0x0001;
inline constexpr std::uint16_t default_assigned = 0x0002;
inline constexpr std::uint16_t oversample = 0x0004;
inline constexpr std::uint16_t fixed_content = 0x0010;
inline constexpr std::uint16_t virtual_content = 0x0020;
inline constexpr std::uint16_t download_anyway = 0x0040;
inline constexpr std::uint16_t from_module = 0x0080;
inline constexpr std::uint16_t module_align = 0x0100;
inline constexpr std::uint16_t depend_on_slot = 0x0200;
inline constexpr std::uint16_t depend_on_slot_group = 0x0400;
inline constexpr std::uint16_t overwritten_by_module = 0x0800;
}  // namespace pdo_flag
inline constexpr std::uint8_t pdo_no_sync_manager = 0xFF;  // PDO not assigned to an SM by default

}  // namespace esi::sii
