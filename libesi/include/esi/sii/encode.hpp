#pragma once
// Image -> bytes. One encoder per category (unit-tested one by one) and the whole-image
// encoder that lays out the header, the category chain and the end marker.

#include <cstdint>
#include <span>
#include <vector>

#include "esi/config_crc.hpp"
#include "esi/sii/image.hpp"

namespace esi::sii {

// The configuration area's CRC-8 (esi/config_crc.hpp), under the name the encoder's users know.
using esi::config_crc;

// Category payloads (without the 4-byte category header). Every payload is padded to a whole
// number of words. The caller guarantees the limits (<=255 strings of <=255 bytes, <=255 PDO
// entries); encoders never fail, they take the low byte.
[[nodiscard]] std::vector<std::uint8_t> encode_strings(const Strings& strings);
[[nodiscard]] std::vector<std::uint8_t> encode_general(const General& general);
// Odd FMMU counts are padded with `pad` (0xFF "not used", as Beckhoff's images do).
[[nodiscard]] std::vector<std::uint8_t> encode_fmmus(const Fmmus& fmmus, std::uint8_t pad = fmmu_usage::unused_ff);
[[nodiscard]] std::vector<std::uint8_t> encode_sync_managers(const SyncManagers& sms);
[[nodiscard]] std::vector<std::uint8_t> encode_pdos(const Pdos& pdos);
[[nodiscard]] std::vector<std::uint8_t> encode_dc(const DcOpModes& dc);
[[nodiscard]] std::vector<std::uint8_t> encode_content(const CategoryContent& content);

// Header words 0x00-0x3F (128 bytes). When `compute_crc` is set, word 7 is the CRC of the
// config area (high byte 0); otherwise header.checksum is written as it is.
[[nodiscard]] std::vector<std::uint8_t> encode_header(const Header& header, bool compute_crc = true);

// Header, categories, end marker 0xFFFF; then padded with 0xFF (erased EEPROM) up to
// `pad_to_bytes` when that is larger. Categories whose payload exceeds 0xFFFF words are the
// builder's business (it reports them); here the length word takes the low 16 bits.
[[nodiscard]] std::vector<std::uint8_t> encode_image(const Image& image, std::size_t pad_to_bytes = 0, bool compute_crc = true);

// Bytes the image occupies before padding: header + categories + end marker.
[[nodiscard]] std::size_t encoded_size(const Image& image);

}  // namespace esi::sii
