// Fuzz target: esi-gen from an ESI source. Any document the reader accepts without errors is
// turned into every output kind (ESI XML, C++ header, C tables, SOES files, process-image
// structs) in memory with the built-in templates: names, numbers and structures from the input
// reach C identifiers, comments and string literals, and must never crash the generator.
//
// Only the first device is generated (as `esi-gen --device` would select it), and inputs above
// 128 KiB are skipped: template rendering costs time in proportion to the model, so a corpus file
// with many devices took over 10 s per input under the sanitizers (0.6 s with the plain esi-gen)
// and was reported as a timeout; scale is what tests/codegen and bench/ measure, the fuzzer is
// after odd names and structures.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "esi/codegen/generate.hpp"
#include "esi/codegen/template_lookup.hpp"
#include "esi/xml/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 128 * 1024) return 0;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const esi::ReadResult read = esi::read_esi(bytes, "fuzz.xml", {.keep_source = false});
    // esi-gen refuses sources with errors (exit code 2) before generating anything.
    if (!read.document || read.diagnostics.has_errors()) return 0;
    esi::codegen::GenerateOptions options;
    options.output_dir = "out";
    static const auto template_dirs = esi::codegen::template_search_path({}, std::nullopt);
    options.template_dirs = template_dirs;
    for (const auto& info : read.document->infos) {
        if (info.devices.empty()) continue;
        const auto& type = info.devices.front().type;
        options.view.device = esi::DeviceSelector{type.product_code.value_or(0), type.revision_no};
        break;
    }
    esi::Diagnostics planning;
    (void)esi::codegen::plan_outputs(*read.document, options, planning);
    if (planning.has_errors()) return 0;
    (void)esi::codegen::generate_outputs(*read.document, options);
    return 0;
}
