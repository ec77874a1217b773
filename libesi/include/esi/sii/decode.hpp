#pragma once
// Bytes -> Image, with every fault found on the way and the byte offset where it sits. The
// checks are those the IgH master's `sii_write` applies before it writes an image (at least 0x41
// words, correct CRC, a category chain that stays in bounds up to 0xFFFF) plus the ones a master
// trips over when it reads the categories (ETG.1000.6 / ETG.2010 record sizes).
//
// Never reads out of bounds, never loops: the walk moves forward by at least one word per
// category, stops at the end of the data and at the EEPROM size the image declares (a real
// EEPROM wraps around there, so a master reading on would loop), and stops on a run of blank
// NOP categories (an erased or zeroed EEPROM).

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/sii/image.hpp"

namespace esi::sii {

struct Fault {
    Severity severity = Severity::error;
    std::string rule;  // stable id, e.g. "sii-crc"
    std::string message;
    std::uint64_t offset = 0;  // byte offset in the image
};

struct DecodedImage {
    Image image;
    std::size_t byte_count = 0;
    bool header_complete = false;  // the 128 header bytes are all there
    std::uint8_t computed_crc = 0;
    bool crc_ok = false;
    std::optional<std::uint64_t> end_offset;  // byte offset of the 0xFFFF end marker
    std::vector<Fault> faults;                // ordered by offset, then discovery

    [[nodiscard]] bool has_errors() const;
    [[nodiscard]] std::size_t count(Severity severity) const;
};

// How many blank NOP categories (type 0, length 0) in a row end the walk.
inline constexpr std::size_t blank_category_run_limit = 16;

// How many categories the walk decodes before it stops with sii-too-many-categories. Real
// images have a few dozen; without a bound an 8 MiB chain of empty categories decodes into two
// million of them, and rendering those as JSON took 2.7 GB (docs/reliability.md).
inline constexpr std::size_t max_categories = 1024;

// How many payload bytes of typed categories (Strings, General, FMMU, SyncM, PDOs, DC) the walk
// decodes into records; categories beyond it are kept as raw bytes (sii-decode-limit). Real
// images have a few KiB of them; a 16 MiB image of PDO categories decodes into two million
// entries, whose JSON dump took 3.5 GB and 84 s (docs/reliability.md).
inline constexpr std::size_t max_decoded_payload_bytes = 64u << 10;

[[nodiscard]] DecodedImage decode_image(std::span<const std::uint8_t> bytes);

// Decoders for one category payload (exposed for unit tests). Faults get offsets relative to
// `payload_offset`, the image offset of the payload's first byte.
[[nodiscard]] CategoryContent decode_content(std::uint16_t type, std::span<const std::uint8_t> payload,
                                             std::uint64_t payload_offset, std::vector<Fault>& faults);

// The faults as library diagnostics for `path`; the message starts with the byte offset.
[[nodiscard]] Diagnostics to_diagnostics(const std::vector<Fault>& faults, const std::string& path);

}  // namespace esi::sii
