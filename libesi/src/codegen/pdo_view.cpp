// The PDO part of the view: RxPdo/TxPdo elements with their entries, the entries' bit offsets
// inside the PDO and the 32-bit mapping value a 0x16xx/0x1Axx sub-entry holds.

#include "codegen/values.hpp"
#include "codegen/view_parts.hpp"
#include "esi/codegen/identifier.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::codegen {

const BasicType* pdo_entry_basic_type(const PdoEntry& entry, const Dictionary* dictionary) {
    if (entry.data_type) {
        const TypeName parsed = parse_type_name(*entry.data_type);
        if (parsed.basic && parsed.kind != TypeName::Kind::array) return parsed.basic;
        const std::string_view standard = standard_type_name_for(trim(*entry.data_type));
        if (!standard.empty()) return find_basic_type(standard);
    }
    if (!dictionary || entry.is_padding()) return nullptr;
    const Object* object = dictionary->find_object(entry.index);
    if (!object) return nullptr;
    const ObjectLayout layout = layout_of(dictionary, *object);
    const ObjectEntry* e = layout.entry(entry.effective_subindex());
    return e ? e->basic : nullptr;
}

ViewValue pdos_view(const Device& device, PdoDirection direction, const ViewContext& context) {
    ViewArena& arena = *context.arena;
    const Dictionary* dictionary = device.dictionary();
    ListBuilder list(arena);
    IdentifierScope pdo_scope;
    for (const Pdo& pdo : device.pdos(direction)) {
        const std::string name = primary_text(pdo.names);
        const ShortText index_hex4 = plain_hex_text(pdo.index, 4);
        ObjectBuilder p(arena);
        p.add("position", list.size());
        p.add("index", pdo.index);
        p.add("index_hex", hex_text(pdo.index, 4));
        p.add("index_hex4", index_hex4);
        p.add("name", name);
        p.add("c_name", pdo_scope.claim(c_identifier(name, std::string(direction == PdoDirection::rx ? "rxpdo_" : "txpdo_") + index_hex4.str()),
                                        std::string_view(index_hex4)));
        p.add("name_literal", c_string_literal(name));
        p.add("comment", c_comment_text(name));
        p.add("direction", ViewValue::of_static(direction == PdoDirection::rx ? "rx" : "tx"));
        p.add("has_sm", pdo.sm.has_value());
        p.add("sm", pdo.sm);
        p.add("fixed", pdo.fixed.value_or(false));
        p.add("mandatory", pdo.mandatory.value_or(false));
        p.add("virtual", pdo.is_virtual.value_or(false));
        {
            ListBuilder excludes(arena);
            for (const auto& x : pdo.excludes) {
                ObjectBuilder exclude(arena);
                exclude.add("index", x.index);
                exclude.add("index_hex", hex_text(x.index, 4));
                excludes.add(exclude.finish());
            }
            p.add("excludes", excludes.finish());
        }

        ListBuilder entries(arena);
        std::uint64_t offset = 0;
        for (const PdoEntry& e : pdo.entries) {
            const BasicType* basic = pdo_entry_basic_type(e, dictionary);
            std::string entry_name = primary_text(e.names);
            if (entry_name.empty() && !e.is_padding() && dictionary) {
                if (const Object* o = dictionary->find_object(e.index)) entry_name = primary_text(o->names);
            }
            const std::uint32_t subindex = e.effective_subindex();
            // PDO mapping entry value (ETG.1000.6, objects 0x1600/0x1A00): index, sub-index, bit length.
            const std::uint32_t mapping = ((e.index & 0xFFFFu) << 16) | ((subindex & 0xFFu) << 8) | (e.bit_len & 0xFFu);
            ObjectBuilder j(arena);
            j.add("index", e.index);
            j.add("index_hex", hex_text(e.index, 4));
            j.add("subindex", subindex);
            j.add("subindex_hex", hex_text(subindex, 2));
            j.add("bit_length", e.bit_len);
            j.add("bit_offset", offset);
            j.add("is_padding", e.is_padding());
            j.add("name", entry_name);
            j.add("name_literal", c_string_literal(entry_name));
            j.add("comment", c_comment_text(entry_name));
            j.add("data_type", basic ? ViewValue::of_static(basic->esi_name) : arena.string(e.data_type.value_or("")));
            j.add("mapping_value", mapping);
            j.add("mapping_value_hex", hex_text(mapping, 8));
            j.add("pdo_index_hex", hex_text(pdo.index, 4));
            entries.add(j.finish());
            offset += e.bit_len;
        }
        p.add("bit_size", offset);
        p.add("byte_size", (offset + 7) / 8);
        p.add("entry_count", pdo.entries.size());
        p.add("entries", entries.finish());
        list.add(p.finish());
    }
    return list.finish();
}

}  // namespace esi::codegen
