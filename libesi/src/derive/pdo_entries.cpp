// PDO entries take BitLen, DataType and Name from the object they map, so that the three cannot
// disagree with the dictionary (a signed object described as UDINT reaches OP without
// complaint and the master reads the wrong sign). An entry that names a missing object or sub-index, or an object that
// is not PDO-mappable in the entry's direction (SDO abort 0604 0041, STÖBER §7.2.3), is an error
// at the entry. Explicit values are kept, but one that contradicts the object is an error too.

#include "derive/steps.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::derive {

namespace {

std::string entry_ref(const PdoEntry& e) {
    return hex4(e.index) + ":" + std::to_string(e.effective_subindex());
}

// The DataType text a PDO entry carries: the type's own name when it is a basic type
// (UINT, STRING(8) …), else the basic type it resolves to (an enum DT0800EN03 maps as its base).
std::string entry_type_name(const ObjectEntry& entry) {
    const TypeName parsed = parse_type_name(entry.type);
    if (parsed.kind != TypeName::Kind::named) return canonical_type_name(entry.type);
    if (entry.basic) return std::string(entry.basic->esi_name);
    return entry.type;
}

bool mappable(const ObjectFlags* flags, PdoDirection direction) {
    if (!flags || !flags->pdo_mapping) return false;
    for (char c : *flags->pdo_mapping) {
        const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if ((direction == PdoDirection::rx && u == 'R') || (direction == PdoDirection::tx && u == 'T')) return true;
    }
    return false;
}

}  // namespace

void derive_pdo_entries(std::vector<Pdo>& pdos, const Dictionary* dictionary, Context& context) {
    const bool have_objects = dictionary && !dictionary->objects.empty();
    std::map<std::uint32_t, const Object*> objects;
    if (have_objects) objects = object_index(*dictionary);
    std::map<std::uint32_t, ObjectLayout> layouts;

    for (Pdo& pdo : pdos) {
        const std::string_view direction = pdo.direction == PdoDirection::rx ? "RxPDO" : "TxPDO";
        for (PdoEntry& e : pdo.entries) {
            if (e.is_padding()) {
                if (e.bit_len == 0) context.error(e.pos, "derive-pdo-entry", "a padding entry needs a bit length (pad: 8)");
                continue;
            }
            const auto it = objects.find(e.index);
            if (it == objects.end()) {
                if (have_objects)
                    context.error(e.pos, "derive-pdo-entry-object",
                                  std::string(direction) + " " + hex4(pdo.index) + " maps " + hex4(e.index) +
                                      ", which is not in the object dictionary");
                else if (e.bit_len == 0)
                    context.error(e.pos, "derive-pdo-entry-object",
                                  "entry " + entry_ref(e) + " names no object of this device; give its bit_len, data_type and name");
                continue;
            }
            const Object& object = *it->second;
            auto layout_it = layouts.find(e.index);
            if (layout_it == layouts.end()) layout_it = layouts.emplace(e.index, layout_of(dictionary, object)).first;
            const ObjectEntry* entry = layout_it->second.entry(e.effective_subindex());
            if (!entry) {
                context.error(e.pos, "derive-pdo-entry-object",
                              std::string(direction) + " " + hex4(pdo.index) + " maps " + entry_ref(e) + ", but object " +
                                  hex4(e.index) + " has no sub-index " + std::to_string(e.effective_subindex()));
                continue;
            }
            if (!mappable(entry->flags, pdo.direction)) {
                // The flags that count are the mapped sub-index's own: on an ARRAY or RECORD the
                // object's `pdo:` does not reach a sub-index of a declared data type.
                const std::string want = pdo.direction == PdoDirection::rx ? "rx" : "tx";
                const std::string advice =
                    e.effective_subindex() == 0
                        ? "give the object pdo: " + want
                        : "give sub-index " + std::to_string(e.effective_subindex()) + " pdo: " + want + " (under the object's " +
                              "entries, or in its data type's sub-items when the object names one)";
                context.error(e.pos, "derive-pdo-entry-mapping",
                              std::string(direction) + " " + hex4(pdo.index) + " maps " + entry_ref(e) + " (" + entry->name +
                                  "), which is not mappable into " + std::string(direction) + "s; " + advice);
                continue;
            }
            if (e.bit_len == 0) {
                e.bit_len = static_cast<std::uint32_t>(entry->bit_size);
                e.bit_len_pos = e.pos;
            } else if (entry->bit_size != 0 && e.bit_len != entry->bit_size) {
                context.error(e.bit_len_pos.known() ? e.bit_len_pos : e.pos, "derive-pdo-entry-bitlen",
                              "entry " + entry_ref(e) + " has bit_len " + std::to_string(e.bit_len) + ", but " + entry->name +
                                  " is " + entry->type + " (" + std::to_string(entry->bit_size) + " bits)");
            }
            const std::string type = entry_type_name(*entry);
            if (!e.data_type) {
                e.data_type = type;
                e.data_type_pos = e.pos;
            } else if (!type.empty() && canonical_type_name(*e.data_type) != canonical_type_name(type) &&
                       canonical_type_name(*e.data_type) != canonical_type_name(entry->type)) {
                context.error(e.data_type_pos.known() ? e.data_type_pos : e.pos, "derive-pdo-entry-type",
                              "entry " + entry_ref(e) + " has data_type " + *e.data_type + ", but " + entry->name + " is " + type);
            }
            if (e.names.empty()) e.names.push_back(LocalizedText{entry->name, std::nullopt, e.pos});
        }
    }
}

}  // namespace esi::derive
