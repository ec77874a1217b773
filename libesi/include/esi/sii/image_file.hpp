#pragma once
// An SII image as a file, in the formats it leaves the tool in: raw binary (what
// `ethercat sii_write` and SOEM's eepromtool -w take), Intel HEX (eepromtool -wi, EEPROM
// programmers) and a C array (firmware that emulates the EEPROM, as EEPROM_generator's eeprom.h).
// And the way back from bin or HEX.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace esi::sii {

enum class ImageFormat { bin, hex, c };

// "bin", "hex", "c"; false on anything else.
[[nodiscard]] bool parse_image_format(std::string_view text, ImageFormat& out);

// Intel HEX: 16 data bytes per record, type 04 extended linear address records when the image
// passes 64 KiB, the EOF record; LF line ends.
[[nodiscard]] std::string to_intel_hex(std::span<const std::uint8_t> bytes);

// A C translation unit defining `const uint8_t <name>[N]` and `<name>_size`; `comment` goes
// into the leading comment (e.g. the device identity).
[[nodiscard]] std::string to_c_array(std::span<const std::uint8_t> bytes, std::string_view name = "sii_eeprom",
                                     std::string_view comment = {});

[[nodiscard]] std::string format_image(std::span<const std::uint8_t> bytes, ImageFormat format,
                                       std::string_view c_name = "sii_eeprom", std::string_view comment = {});

struct HexParseResult {
    std::optional<std::vector<std::uint8_t>> bytes;
    std::string error;      // set when bytes is absent
    std::size_t line = 0;   // 1-based line of the error
};

// Parses Intel HEX (record types 00, 01, 02, 04; checksums verified). Gaps are filled with 0xFF;
// the image starts at address 0. Addresses beyond 16 MiB are refused.
[[nodiscard]] HexParseResult parse_intel_hex(std::string_view text);

// True when the bytes look like Intel HEX (first non-blank character ':').
[[nodiscard]] bool looks_like_intel_hex(std::string_view bytes);

// The largest image read (binary, or the highest Intel HEX address): twice the 8 MiB word 0x3E
// can describe, so that oversized dumps are still shown, and a bound on memory for any file.
inline constexpr std::size_t max_image_bytes = 16u << 20;

// An image as it arrives: raw binary, or Intel HEX (recognised by its leading ':').
struct LoadedImage {
    std::optional<std::vector<std::uint8_t>> bytes;
    std::string error;  // why bytes is absent
    bool was_hex = false;
};
[[nodiscard]] LoadedImage load_image(std::string_view raw);
[[nodiscard]] LoadedImage load_image_file(const std::filesystem::path& path);

}  // namespace esi::sii
