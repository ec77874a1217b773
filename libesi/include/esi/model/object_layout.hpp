#pragma once
// How a Dictionary object looks over SDO: its object code and its sub-entries with resolved
// types, sizes, offsets, flags and values. Lint rules, generators, SII, diff and import all ask
// this one function instead of re-walking DataTypes.

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "esi/data_types.hpp"
#include "esi/model/dictionary.hpp"

namespace esi {

// A type name followed through DataType/BaseType to what it finally is.
struct ResolvedType {
    const DataType* definition = nullptr;  // the DataType element the name refers to, if any
    const BasicType* basic = nullptr;      // the basic type it ends in (nullptr for structures)
    std::uint64_t bit_size = 0;            // from the definition, else implied by the name
    bool known = false;                    // the name is a basic type or a defined DataType
    bool cycle = false;                    // BaseType chain loops or is too deep
    bool is_array = false;                 // ArrayInfo or "ARRAY [..] OF"
    bool is_structure = false;             // has SubItems
    std::int64_t array_lower_bound = 0;
    std::uint64_t array_elements = 0;
    std::string element_type;  // array element type name
};

[[nodiscard]] ResolvedType resolve_type(const Dictionary* dictionary, std::string_view type_name);

// The DataTypes of one Dictionary by name, for callers that resolve many names (lint runs
// resolve every object's and sub-item's type): the overloads below give the same answers as
// the Dictionary ones, with a hash lookup per name instead of a scan of DataTypes. Holds
// pointers into the Dictionary, which must outlive it unchanged.
class DataTypeIndex {
public:
    explicit DataTypeIndex(const Dictionary* dictionary);
    [[nodiscard]] const Dictionary* dictionary() const { return dictionary_; }
    // The first DataType of that exact name, as Dictionary::find_data_type.
    [[nodiscard]] const DataType* find(std::string_view name) const;

private:
    const Dictionary* dictionary_;
    std::unordered_map<std::string_view, const DataType*> by_name_;
    // DataTypes named like a basic type (Beckhoff lists "UINT" with its BitSize), by the basic
    // type's place in basic_types(): most names a layout resolves are basic, and this spares
    // them the hash lookup.
    std::vector<const DataType*> basic_named_;
};

[[nodiscard]] ResolvedType resolve_type(const DataTypeIndex& types, std::string_view type_name);

enum class ObjectCode { var, array, record };
[[nodiscard]] std::string_view to_string(ObjectCode code);

struct ObjectEntry {
    std::uint32_t subindex = 0;
    std::string name;
    std::string type;                   // type name of the entry (element type for arrays)
    const BasicType* basic = nullptr;   // resolved basic type; nullptr when unresolved/structured
    std::uint64_t bit_size = 0;
    std::uint64_t bit_offset = 0;       // within the object
    const ObjectFlags* flags = nullptr;  // the sub-item's flags, else the object's
    const ObjectInfo* info = nullptr;    // default/min/max for this entry, if given
    const DataTypeSubItem* type_item = nullptr;  // the SubItem that defines it (records/arrays)
};

struct ObjectLayout {
    ObjectCode code = ObjectCode::var;
    std::vector<ObjectEntry> entries;  // VAR: one entry, subindex 0
    [[nodiscard]] const ObjectEntry* entry(std::uint32_t subindex) const;
};

[[nodiscard]] ObjectLayout layout_of(const Dictionary* dictionary, const Object& object);
[[nodiscard]] ObjectLayout layout_of(const DataTypeIndex& types, const Object& object);

}  // namespace esi
