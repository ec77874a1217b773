// The output kinds of esi-gen. Each is a list of files rendered from templates or produced in
// code; other back ends join by adding an entry here.

#include "esi/codegen/generate.hpp"
#include "esi/xml/writer.hpp"
#include "sii_image.hpp"

namespace esi::codegen {

namespace {

Diagnostics produce_esi(const ProduceContext& context, std::string& content) {
    Diagnostics diagnostics;
    content = write_esi(context.document);
    if (content.empty())
        diagnostics.emplace(Severity::error, "codegen-esi-writer", "the ESI writer produced no output", context.document.path, {});
    return diagnostics;
}

}  // namespace

const std::vector<OutputKind>& output_kinds() {
    static const std::vector<OutputKind> kinds = {
        {"esi", "ESI XML of the vendor catalogue", OutputScope::document, {{"{stem}.xml", "", &produce_esi}}},
        {"cpp", "C++17 object-dictionary header: constexpr tables, index constants, lookup", OutputScope::device,
         {{"object_dictionary.hpp", "object_dictionary.hpp.mustache", nullptr}}},
        {"c", "stack-neutral C99 slave tables: OD, PDO mapping and assignment, SM and ESC configuration", OutputScope::device,
         {{"slave_tables.h", "slave_tables.h.mustache", nullptr}, {"slave_tables.c", "slave_tables.c.mustache", nullptr}}},
        {"soes", "SOES object list, utypes.h and ecat_options.h", OutputScope::device,
         {{"objectlist.c", "soes_objectlist.c.mustache", nullptr},
          {"utypes.h", "soes_utypes.h.mustache", nullptr},
          {"ecat_options.h", "soes_ecat_options.h.mustache", nullptr}}},
        {"structs", "packed C/C++ structs of the default RxPDO/TxPDO process images", OutputScope::device,
         {{"process_image.h", "process_image.h.mustache", nullptr}}},
        {"sii", "SII EEPROM image of the device, raw binary and Intel HEX (as esi-sii build)", OutputScope::device,
         {{"eeprom.bin", "", &produce_sii_binary}, {"eeprom.hex", "", &produce_sii_intel_hex}}},
    };
    return kinds;
}

const OutputKind* find_output_kind(std::string_view name) {
    for (const auto& kind : output_kinds())
        if (kind.name == name) return &kind;
    return nullptr;
}

}  // namespace esi::codegen
