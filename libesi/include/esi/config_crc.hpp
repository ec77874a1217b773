#pragma once
// The checksum of the SII configuration area (words 0-6, ConfigData), which the ESC checks when
// it loads the EEPROM at power-on and the SII builder writes into word 7. One function for both:
// the emulated ESC (esc layer) and the SII encoder and decoder (sii layer).

#include <cstdint>
#include <span>

namespace esi {

// CRC-8 of the configuration area: polynomial x^8+x^2+x+1 (0x07), initial value 0xFF, no
// reflection, no final XOR, over bytes 0-13 (ESC data sheet Section I; ETG.2010).
[[nodiscard]] std::uint8_t config_crc(std::span<const std::uint8_t> config_area);

}  // namespace esi
