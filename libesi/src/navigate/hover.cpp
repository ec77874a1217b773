// Hover: what the token under the cursor names, from the definitions of its device.

#include <string>

#include "esi/data_types.hpp"
#include "esi/plural.hpp"
#include "navigate/format.hpp"
#include "navigate/index.hpp"

namespace esi::navigate {

namespace {

void add_fact(std::string& out, std::string_view label, std::string_view value) {
    if (value.empty()) return;
    out += "- ";
    out += label;
    out += ": ";
    out += value;
    out += '\n';
}

// "8 bits (1 byte)": process data is sized in bits, SMs and frames in bytes.
std::string size_text(std::uint64_t bits) {
    const std::uint64_t bytes = (bits + 7) / 8;
    return bits_text(std::to_string(bits)) + " (" + std::to_string(bytes) + (bytes == 1 ? " byte)" : " bytes)");
}

std::string object_hover(const Index& index, const Scope& scope, const Occurrence& occurrence) {
    const ObjectDef* object = scope.find_object(occurrence.key);
    const std::string shown = format_index(occurrence.key, index.yaml);
    if (!object) return "Object " + shown + " is not in the dictionary of " + scope_title(scope) + ".\n";
    std::string out;
    const DataTypeDef* type = scope.find_data_type(object->type);
    if (occurrence.sub && *occurrence.sub != 0 && type) {
        for (const auto& item : type->sub_items) {
            if (item.subindex != occurrence.sub) continue;
            out += "**" + shown + ":" + format_subindex(*occurrence.sub, index.yaml) + " " + item.name + "**  \n";
            out += "sub-item of " + shown + " " + object->name + "\n\n";
            add_fact(out, "type", code(item.type));
            add_fact(out, "size", bits_text(item.bit_size));
            add_fact(out, "bit offset", item.bit_offset);
            add_fact(out, "access", item.access.empty() ? object->access : item.access);
            add_fact(out, "PDO mapping", item.pdo_mapping.empty() ? object->pdo_mapping : item.pdo_mapping);
            for (const auto& [name, value] : object->sub_defaults)
                if (name == item.name) add_fact(out, "default", code(value));
            return out;
        }
    }
    out += "**" + shown + " " + object->name + "**\n\n";
    add_fact(out, "type", code(object->type));
    add_fact(out, "size", bits_text(object->bit_size));
    add_fact(out, "access", object->access);
    add_fact(out, "PDO mapping", object->pdo_mapping);
    add_fact(out, "default", code(object->default_value));
    if (type && !type->sub_items.empty()) out += "- sub-items: " + std::to_string(type->sub_items.size()) + "\n";
    return out;
}

std::string data_type_hover(const Scope& scope, std::string_view name) {
    const DataTypeDef* type = scope.find_data_type(name);
    if (!type) {
        if (const BasicType* basic = find_basic_type(name)) {
            std::string out = "**" + std::string(basic->esi_name) + "** (" + std::string(basic->coe_name) + ", " +
                              format_coe_code(basic->coe_code) + ")";
            if (basic->bit_size != 0) out += ": " + bits_text(std::to_string(basic->bit_size));
            return out + "\n";
        }
        return "DataType " + code(name) + " is not defined in " + scope_title(scope) + ".\n";
    }
    std::string out = "**DataType " + type->name + "**";
    if (!type->bit_size.empty()) out += ": " + bits_text(type->bit_size);
    out += "\n\n";
    if (!type->base_type.empty()) add_fact(out, "base type", code(type->base_type) + type->array);
    if (!type->sub_items.empty()) {
        out += "\n| SubIdx | Name | Type | BitSize | BitOffs |\n|---:|---|---|---:|---:|\n";
        for (const auto& item : type->sub_items) {
            out += "| " + (item.subindex ? std::to_string(*item.subindex) : std::string()) + " | " + item.name + " | " +
                   item.type + " | " + item.bit_size + " | " + item.bit_offset + " |\n";
        }
    }
    return out;
}

std::string pdo_hover(const Index& index, const Scope& scope, std::uint32_t key) {
    const PdoDef* pdo = scope.find_pdo(key);
    if (!pdo) return "PDO " + format_index(key, index.yaml) + " is not defined in " + scope_title(scope) + ".\n";
    std::string out = "**" + std::string(pdo->tx ? "TxPdo " : "RxPdo ") + format_index(pdo->index, index.yaml) + " " +
                      pdo->name + "**\n\n";
    add_fact(out, "size", size_text(pdo->bit_size()));
    add_fact(out, "entries", std::to_string(pdo->entries.size()));
    if (pdo->sm) {
        std::string sm = "SM" + std::to_string(*pdo->sm);
        if (const SmDef* def = scope.find_sm(*pdo->sm); def && !def->role.empty()) sm += " (" + def->role + ")";
        add_fact(out, "assigned to", sm);
    } else {
        add_fact(out, "assigned to", "no SM by default");
    }
    return out;
}

std::string_view role_meaning(std::string_view role) {
    if (role == "MBoxOut") return "mailbox out, master to device";
    if (role == "MBoxIn") return "mailbox in, device to master";
    if (role == "Outputs") return "process data outputs, master to device";
    if (role == "Inputs") return "process data inputs, device to master";
    return "";
}

std::string sm_hover(const Index& index, const Scope& scope, std::uint32_t number) {
    const SmDef* sm = scope.find_sm(number);
    if (!sm) return "SM" + std::to_string(number) + " is not defined in " + scope_title(scope) + ".\n";
    std::string out = "**SM" + std::to_string(sm->number) + " " + sm->role + "**";
    if (const std::string_view meaning = role_meaning(sm->role); !meaning.empty()) out += " (" + std::string(meaning) + ")";
    out += "\n\n";
    add_fact(out, "start address", sm->start_address);
    if (!sm->default_size.empty())
        add_fact(out, "default size", sm->default_size + (sm->default_size == "1" ? " byte" : " bytes"));
    add_fact(out, "control byte", sm->control_byte);
    add_fact(out, "enable", sm->enable);
    std::uint64_t bits = 0;
    std::string mapped;
    for (const auto& pdo : scope.pdos) {
        if (pdo.sm != sm->number) continue;
        bits += pdo.bit_size();
        mapped += "  - " + std::string(pdo.tx ? "TxPdo " : "RxPdo ") + format_index(pdo.index, index.yaml) + " " + pdo.name +
                  " (" + esi::counted(pdo.bit_size(), "bit") + ")\n";
    }
    if (!mapped.empty())
        out += "- mapped by default: " + size_text(bits) + "\n" +
               mapped;
    return out;
}

}  // namespace

std::optional<Hover> hover(const Index& index, Position position) {
    const auto offset = index.lines.offset_of(position);
    if (!offset) return std::nullopt;
    const Occurrence* occurrence = index.occurrence_at(*offset);
    if (!occurrence || occurrence->scope >= index.scopes.size()) return std::nullopt;
    const Scope& scope = index.scopes[occurrence->scope];
    Hover result;
    result.range = index.range(occurrence->span);
    switch (occurrence->target) {
        case Target::object: result.markdown = object_hover(index, scope, *occurrence); break;
        case Target::data_type: result.markdown = data_type_hover(scope, index.token(occurrence->span)); break;
        case Target::pdo: result.markdown = pdo_hover(index, scope, occurrence->key); break;
        case Target::sync_manager: result.markdown = sm_hover(index, scope, occurrence->key); break;
    }
    while (result.markdown.ends_with("\n\n")) result.markdown.pop_back();
    return result;
}

}  // namespace esi::navigate
