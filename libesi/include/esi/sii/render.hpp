#pragma once
// Renders a decoded image as text or JSON (esi-sii dump). Pure functions; the CLI prints.

#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"
#include "esi/sii/decode.hpp"

namespace esi::sii {

// Every header word and category in readable form, then the faults with their offsets.
[[nodiscard]] std::string render_dump_text(const DecodedImage& image, std::string_view path);

// {"path", "bytes", "crc": {...}, "header": {...}, "categories": [{offset, type, name, words,
// content}], "end_offset", "faults": [{offset, severity, rule, message}],
// "summary": {errors, warnings, infos}}. Strings are UTF-8 (ISO-8859-1 bytes converted).
[[nodiscard]] std::string render_dump_json(const DecodedImage& image, std::string_view path);

// One line per fault: "PATH: byte 0x0080: error: message [rule]".
[[nodiscard]] std::string render_faults_text(const DecodedImage& image, std::string_view path);

// One line per diagnostic, "path:line:col: severity: message [rule]", notes indented below.
[[nodiscard]] std::string render_diagnostics_text(const Diagnostics& diagnostics);

// esi-sii check: the image's own faults, then the ESI/image mismatches, then a summary line.
[[nodiscard]] std::string render_check_text(const DecodedImage& image, std::string_view image_path,
                                            const Diagnostics& mismatches, std::string_view device_label);

}  // namespace esi::sii
