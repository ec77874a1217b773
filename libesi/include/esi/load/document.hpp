#pragma once
// One input file as a document, whatever its kind: an ESI file (XML) or a YAML device source.
// The tools that accept either (esi-gen, esi-sii, esi-diff) load through this, so they agree on
// which kind a file is and report its problems the same way.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/model/limits.hpp"

namespace esi {

enum class DocumentFormat { esi_xml, yaml_source };

// By content: after a byte-order mark and blanks, an XML document starts with '<' (in UTF-8 or
// UTF-16) and a YAML source never does. A file with nothing but blanks goes by its extension
// (.yaml/.yml: YAML, anything else: XML), so its error message speaks of the format meant.
[[nodiscard]] DocumentFormat document_format(std::string_view bytes, const std::filesystem::path& path);

struct LoadedDocument {
    DocumentFormat format = DocumentFormat::esi_xml;
    std::optional<EsiDocument> document;  // absent when the file is unusable
    Diagnostics diagnostics;              // the front end's, with the file's positions
    // The limits a YAML source declares per device (`limits:`); empty for ESI files.
    std::vector<std::pair<DeviceSelector, Limits>> device_limits;

    // A document that can be used: present, and for a YAML source without errors (an ESI file
    // with rule findings is still the vendor's file; a YAML source with errors is not derived).
    [[nodiscard]] bool usable() const;
};

[[nodiscard]] LoadedDocument load_document(std::string bytes, const std::string& path);
// Reads the file (bounded, see esi/io/read_file.hpp); an unreadable file is an io-error.
[[nodiscard]] LoadedDocument load_document_file(const std::filesystem::path& path);

}  // namespace esi
