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

Json pdos_view(const Device& device, PdoDirection direction) {
    const Dictionary* dictionary = device.dictionary();
    Json list = Json::array();
    IdentifierScope pdo_scope;
    for (const Pdo& pdo : device.pdos(direction)) {
        const std::string name = primary_text(pdo.names);
        char index_hex4[8];
        std::snprintf(index_hex4, sizeof index_hex4, "%04X", pdo.index);
        Json p;
        p["position"] = list.size();
        p["index"] = pdo.index;
        p["index_hex"] = hex(pdo.index, 4);
        p["index_hex4"] = index_hex4;
        p["name"] = name;
        p["c_name"] = pdo_scope.claim(c_identifier(name, std::string(direction == PdoDirection::rx ? "rxpdo_" : "txpdo_") + index_hex4),
                                      index_hex4);
        p["name_literal"] = c_string_literal(name);
        p["comment"] = c_comment_text(name);
        p["direction"] = direction == PdoDirection::rx ? "rx" : "tx";
        p["has_sm"] = pdo.sm.has_value();
        p["sm"] = pdo.sm ? Json(*pdo.sm) : Json(nullptr);
        p["fixed"] = pdo.fixed.value_or(false);
        p["mandatory"] = pdo.mandatory.value_or(false);
        p["virtual"] = pdo.is_virtual.value_or(false);
        Json excludes = Json::array();
        for (const auto& x : pdo.excludes) excludes.push_back(Json{{"index", x.index}, {"index_hex", hex(x.index, 4)}});
        p["excludes"] = std::move(excludes);

        Json entries = Json::array();
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
            Json j;
            j["index"] = e.index;
            j["index_hex"] = hex(e.index, 4);
            j["subindex"] = subindex;
            j["subindex_hex"] = hex(subindex, 2);
            j["bit_length"] = e.bit_len;
            j["bit_offset"] = offset;
            j["is_padding"] = e.is_padding();
            j["name"] = entry_name;
            j["name_literal"] = c_string_literal(entry_name);
            j["comment"] = c_comment_text(entry_name);
            j["data_type"] = basic ? std::string(basic->esi_name) : e.data_type.value_or("");
            j["mapping_value"] = mapping;
            j["mapping_value_hex"] = hex(mapping, 8);
            j["pdo_index_hex"] = hex(pdo.index, 4);
            entries.push_back(std::move(j));
            offset += e.bit_len;
        }
        p["bit_size"] = offset;
        p["byte_size"] = (offset + 7) / 8;
        p["entry_count"] = pdo.entries.size();
        p["entries"] = std::move(entries);
        list.push_back(std::move(p));
    }
    return list;
}

}  // namespace esi::codegen
