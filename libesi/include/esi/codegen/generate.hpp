#pragma once
// esi-gen's back end: the list of output kinds and the generation of every output file of a
// document, in memory, ready for write_files_atomically. Nothing here touches the output
// directory; templates are read from the search path.
//
// Output kinds (`--only`):
//   esi      the vendor catalogue as ESI XML (esi::write_esi), one file for the document
//   cpp      C++17 object-dictionary header (constexpr tables, index constants, lookup)
//   c        stack-neutral C99 slave tables (OD, PDO mapping/assignment, SM and ESC config)
//   soes     SOES object list, utypes.h and ecat_options.h
//   structs  packed C/C++ structs of the default RxPDO/TxPDO process images
//   sii      the SII EEPROM image (eeprom.bin, eeprom.hex), as esi-sii build writes it
// Per-device kinds go straight into the output directory when the document yields one device,
// else into one sub-directory per device, named after the device's c_name.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "esi/codegen/model_view.hpp"
#include "esi/diagnostic.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::codegen {

enum class OutputScope { document, device };

struct ProduceContext;
// Produces one file in code rather than from a template (ESI XML, the SII image).
using Producer = Diagnostics (*)(const ProduceContext& context, std::string& content);

struct OutputArtifact {
    std::string file_name;      // "{stem}" is replaced by the source file's stem
    std::string template_name;  // rendered from this template, or
    Producer produce = nullptr; // produced by this function
};

struct OutputKind {
    std::string name;  // the --only value
    std::string summary;
    OutputScope scope = OutputScope::device;
    std::vector<OutputArtifact> artifacts;
};

// Every output kind, in the order they are generated. Add a kind here to extend esi-gen.
[[nodiscard]] const std::vector<OutputKind>& output_kinds();
[[nodiscard]] const OutputKind* find_output_kind(std::string_view name);

// Errors (with a did-you-mean) for names in `only` that are not output kinds.
[[nodiscard]] Diagnostics check_output_kinds(const std::vector<std::string>& only);

struct GenerateOptions {
    std::filesystem::path output_dir;
    std::vector<std::string> only;                     // kind names; empty = every kind
    std::vector<std::filesystem::path> template_dirs;  // searched in order (see template_lookup.hpp)
    ViewOptions view;
    // The "sii" kind refuses an image larger than Eeprom/ByteSize instead of leaving out optional
    // content until it fits (esi-gen --strict-size; docs/sii.md §1).
    bool sii_strict_size = false;
    // The "sii" kind refuses an image that switches the PDI off (a device without Eeprom/ConfigData
    // and without `esc:`) instead of warning (esi-gen --strict; docs/sii.md §2).
    bool sii_strict = false;
};

struct ProduceContext {
    const EsiDocument& document;
    const Device* device;  // null for document-scope outputs
    const GenerateOptions& options;
};

struct PlannedFile {
    std::filesystem::path path;  // output_dir / [device dir /] file name
    std::string kind;
    std::string template_name;   // empty for produced files
};

struct GenerateResult {
    std::vector<OutputFile> files;
    Diagnostics diagnostics;  // errors: unknown kind, missing or broken template, no device, ...
};

// The files a run would write, without rendering anything (for build systems: esi-gen
// --list-outputs). Errors leave the list empty.
[[nodiscard]] std::vector<PlannedFile> plan_outputs(const EsiDocument& document, const GenerateOptions& options, Diagnostics& diagnostics);

// Renders every planned file. On any error `files` is empty: a run writes all or nothing.
[[nodiscard]] GenerateResult generate_outputs(const EsiDocument& document, const GenerateOptions& options);

}  // namespace esi::codegen
