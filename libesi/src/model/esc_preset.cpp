// The ESC presets' values. Each row's ConfigData is the one a reference design of the chip's
// vendor (or the stack that targets it) ships, so that an image made from a preset behaves like
// theirs; docs/yaml-format.md ("ESC presets") explains every byte with its datasheet register.

#include "esi/model/esc_preset.hpp"

#include <algorithm>
#include <array>

namespace esi {

namespace {

// Words: 0 = PDI control | ESC configuration << 8, 1 = PDI configuration | SYNC/latch
// configuration << 8, 2 = SYNC pulse length (10 ns), 3 = extended PDI configuration.
constexpr std::array<EscPreset, 10> presets{{
    // Microchip's own LAN9252 reference ESI (SAMD51 + EVB-LAN9252): 0x80 is the LAN9252's
    // SPI/HBI host interface on the ESC's on-chip bus.
    {"lan9252-spi", "Microchip LAN9252", "SPI", "800E00CC8813FF000000", 2048, ""},
    // The SOES EEPROM generator's AX58100 setting: word 5 (0x001A) switches on the SPI pins'
    // drivers (AX58100 "Host Interface Extend Setting and Drive Strength").
    {"ax58100-spi", "ASIX AX58100", "SPI", "050600446400000000001A000000", 2048, ""},
    // ASIX's AX58100 evaluation board (EVB DIO): 16 inputs, 16 outputs, no microcontroller.
    {"ax58100-dio", "ASIX AX58100", "digital I/O", "040D0044102700FF000000000000", 2048, ""},
    // Beckhoff's ET1100 evaluation board FB1111 (SPI slave, MCI8 DC, MCI16 DC, Dig. In/Out);
    // the SPI row drives SYNC0/SYNC1 as outputs (1 µs) as the SOES generator's ET1100 setting.
    {"et1100-spi", "Beckhoff ET1100", "SPI", "050E034464000000", 2048, ""},
    {"et1100-mcu8", "Beckhoff ET1100", "8-bit asynchronous µC", "090E02880000", 2048, ""},
    {"et1100-mcu16", "Beckhoff ET1100", "16-bit asynchronous µC", "080E02880000", 2048, ""},
    {"et1100-dio", "Beckhoff ET1100", "digital I/O", "040F0044102700FF", 2048, ""},
    // ET1200: the same registers as the ET1100 (ESC datasheet section II), SPI as et1100-spi.
    {"et1200-spi", "Beckhoff ET1200", "SPI", "050E034464000000", 2048, ""},
    // Infineon XMC4300/4800 (on-chip ESC) as SOES's XMC4 applications: the EEPROM is emulated in
    // flash, 16 pages of 256 bytes less an 8-byte header, rounded down to 128 bytes = 3968.
    {"xmc4", "Infineon XMC4300/XMC4800", "on-chip bus", "8006810600000000", 3968, ""},
    // TI AM335x/AM437x PRU-ICSS (SOES tiesc_am335x): the firmware update in BOOT uses the
    // bootstrap mailbox 0x1000/0x1200, 512 bytes each.
    {"tiesc", "TI AM335x/AM437x PRU-ICSS", "on-chip bus", "8006E08800000000", 2048, "0010000200120002"},
}};

std::vector<std::uint8_t> decode_hex(std::string_view text) {
    auto value = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return c - 'a' + 10;
    };
    std::vector<std::uint8_t> out(text.size() / 2);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<std::uint8_t>(value(text[2 * i]) * 16 + value(text[2 * i + 1]));
    return out;
}

}  // namespace

std::vector<std::uint8_t> EscPreset::config_bytes() const { return decode_hex(config_data); }

std::vector<std::uint8_t> EscPreset::boot_strap_bytes() const { return decode_hex(boot_strap); }

std::span<const EscPreset> esc_presets() { return presets; }

const EscPreset* find_esc_preset(std::string_view name) {
    const auto it = std::find_if(presets.begin(), presets.end(), [&](const EscPreset& p) { return p.name == name; });
    return it == presets.end() ? nullptr : &*it;
}

const EscPreset* match_esc_preset(std::span<const std::uint8_t> config_data, std::uint32_t eeprom_bytes,
                                  std::span<const std::uint8_t> boot_strap) {
    for (const auto& p : presets) {
        const auto config = p.config_bytes();
        const auto boot = p.boot_strap_bytes();
        if (p.eeprom_bytes == eeprom_bytes && std::ranges::equal(config, config_data) && std::ranges::equal(boot, boot_strap))
            return &p;
    }
    return nullptr;
}

std::string esc_preset_names() {
    std::string out;
    for (const auto& p : presets) {
        if (!out.empty()) out += ", ";
        out += p.name;
    }
    return out;
}

std::optional<std::string_view> pdi_type_name(std::uint8_t pdi_control) {
    // ESC datasheet section II, register 0x0140 "PDI Control".
    switch (pdi_control) {
        case 0x00: return "off (no interface)";
        case 0x01: return "4 digital inputs";
        case 0x02: return "4 digital outputs";
        case 0x03: return "2 digital inputs, 2 digital outputs";
        case 0x04: return "digital I/O";
        case 0x05: return "SPI";
        case 0x06: return "oversampling I/O";
        case 0x07: return "EtherCAT bridge (port 3)";
        case 0x08: return "16-bit asynchronous µC";
        case 0x09: return "8-bit asynchronous µC";
        case 0x0A: return "16-bit synchronous µC";
        case 0x0B: return "8-bit synchronous µC";
        case 0x10: return "32 digital inputs";
        case 0x11: return "24 digital inputs, 8 digital outputs";
        case 0x12: return "16 digital inputs, 16 digital outputs";
        case 0x13: return "8 digital inputs, 24 digital outputs";
        case 0x14: return "32 digital outputs";
        case 0x80: return "on-chip bus";
        default: return std::nullopt;
    }
}

}  // namespace esi
