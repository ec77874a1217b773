#include "check/pdo_entry_type.hpp"

#include "esi/model/object_layout.hpp"
#include "esi/number.hpp"

namespace esi::rules {

EntryType entry_type(const Dictionary* dictionary, const PdoEntry& entry) {
    EntryType out;
    if (!entry.data_type) return out;
    const std::string_view text = trim(*entry.data_type);
    if (text.empty()) return out;
    out.present = true;
    // "UINT16" is not an ESI name even where a Dictionary happens to define a type of that name.
    if (!find_basic_type(text)) out.standard_name = standard_type_name_for(text);
    const ResolvedType resolved = resolve_type(dictionary, text);
    out.known = resolved.known && !resolved.cycle;
    if (!out.known) return out;
    out.basic = resolved.basic;
    out.bit_size = resolved.bit_size;
    return out;
}

}  // namespace esi::rules
