#pragma once
// ESC presets: the EEPROM settings an EtherCAT slave controller needs so that its process data
// interface (PDI) is on when the EEPROM is loaded. SII words 0-6 (ConfigData) are copied by the
// ESC into its registers at power-on: word 0 into PDI control (0x0140) and ESC configuration
// (0x0141), word 1 into PDI configuration (0x0150) and SYNC/latch PDI configuration (0x0151),
// word 2 into the SYNC pulse length (0x0982), word 3 into the extended PDI configuration
// (0x0152-0x0153), word 4 into the station alias. An image with PDI control 0 leaves the
// microcontroller without any access to the ESC, so a device source names its ESC (`esc:`) and
// gets the values from here. Each value and its source is in docs/yaml-format.md ("ESC presets").

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace esi {

struct EscPreset {
    std::string_view name;         // the YAML spelling: `esc: lan9252-spi`
    std::string_view chip;         // for people: "Microchip LAN9252"
    std::string_view interface;    // for people: "SPI"
    std::string_view config_data;  // Eeprom/ConfigData, hexBinary as the reference ESI spells it
    std::uint32_t eeprom_bytes;    // Eeprom/ByteSize the chip family's boards use
    std::string_view boot_strap;   // Eeprom/BootStrap hexBinary; empty when the stack needs none

    [[nodiscard]] std::vector<std::uint8_t> config_bytes() const;
    [[nodiscard]] std::vector<std::uint8_t> boot_strap_bytes() const;
};

// Every preset, in the order the documentation lists them.
[[nodiscard]] std::span<const EscPreset> esc_presets();

// The preset called `name` (exact spelling), or null.
[[nodiscard]] const EscPreset* find_esc_preset(std::string_view name);

// The preset whose ConfigData, ByteSize and BootStrap are exactly these bytes (BootStrap empty
// when absent), or null. Used by the import to write `esc:` where an ESI holds a preset's values.
[[nodiscard]] const EscPreset* match_esc_preset(std::span<const std::uint8_t> config_data, std::uint32_t eeprom_bytes,
                                                std::span<const std::uint8_t> boot_strap);

// "lan9252-spi, ax58100-spi, …": the names for messages.
[[nodiscard]] std::string esc_preset_names();

// The name of a PDI type (register 0x0140, SII word 0 low byte): "SPI", "8-bit asynchronous
// µC", "off (no interface)" for 0; nullopt for a value no ESC datasheet defines.
[[nodiscard]] std::optional<std::string_view> pdi_type_name(std::uint8_t pdi_control);

}  // namespace esi
