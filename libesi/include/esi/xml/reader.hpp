#pragma once
// The ESI XML front end: bytes -> typed model + diagnostics. Tolerant of what vendors ship
// (BOM, UTF-16, ISO-8859-1/Windows-1252, #x and decimal numbers, 0x with a diagnostic,
// 1/0/true/false, several Names, unknown elements kept verbatim). A file that is not well-formed
// XML 1.0 yields a single xml-syntax error at the position of the fault and no document.
// Reading is one pass over the text, a device at a time: a catalogue's parsed XML is never in
// memory as a whole, only the model read from it (docs/performance.md).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

struct ReadOptions {
    // Keep the decoded text in the document (for quoting source lines in reports).
    bool keep_source = true;
    // Nesting depth beyond which unknown elements are not copied (guards against hostile input).
    std::size_t max_verbatim_depth = 256;
};

struct ReadResult {
    std::optional<EsiDocument> document;  // absent when the file could not be read or parsed
    Diagnostics diagnostics;
    // The decoded text; set even when parsing failed, so reports can quote the faulty line.
    SourceTextPtr source;
};

// `path` is used in diagnostics; the bytes may come from anywhere (a file, stdin, memory).
[[nodiscard]] ReadResult read_esi(std::string_view bytes, std::string path, const ReadOptions& options = {});
// Same, taking ownership of the bytes: valid UTF-8 input is used in place, without a copy.
[[nodiscard]] ReadResult read_esi_owned(std::string bytes, std::string path, const ReadOptions& options = {});

// Reads a file; a missing or unreadable file gives an `io-error` diagnostic.
[[nodiscard]] ReadResult read_esi_file(const std::filesystem::path& path, const ReadOptions& options = {});

}  // namespace esi
