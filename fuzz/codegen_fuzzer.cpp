// Fuzz target: esi-gen from an ESI source. Any document the reader accepts without errors is
// turned into every output kind (ESI XML, C++ header, C tables, SOES files, process-image
// structs) in memory with the built-in templates: names, numbers and structures from the input
// reach C identifiers, comments and string literals, and must never crash the generator.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "esi/codegen/generate.hpp"
#include "esi/codegen/template_lookup.hpp"
#include "esi/xml/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const esi::ReadResult read = esi::read_esi(bytes, "fuzz.xml", {.keep_source = false});
    // esi-gen refuses sources with errors (exit code 2) before generating anything.
    if (!read.document || read.diagnostics.has_errors()) return 0;
    static const esi::codegen::GenerateOptions options = [] {
        esi::codegen::GenerateOptions o;
        o.output_dir = "out";
        o.template_dirs = esi::codegen::template_search_path({}, std::nullopt);
        return o;
    }();
    esi::Diagnostics planning;
    (void)esi::codegen::plan_outputs(*read.document, options, planning);
    if (planning.has_errors()) return 0;
    (void)esi::codegen::generate_outputs(*read.document, options);
    return 0;
}
