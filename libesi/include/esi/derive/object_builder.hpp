#pragma once
// Builds RECORD and ARRAY objects the way ETG.2000 dictionaries describe them, so the YAML
// front end and derivation (0x1018, 0x1C00, 0x16xx …) produce the same shapes:
//   RECORD: Object/Type "DTxxxx", a DataType with SubItem "SubIndex 000" (USINT, BitOffs 0)
//           followed by the entries; the first entry starts at bit 16 and entries of 8 bits or
//           more start on a byte boundary (the layout of DT1018 and DT1C32 in ETG/Beckhoff files).
//   ARRAY:  Object/Type "DTxxxx", a DataType with SubItem "SubIndex 000" and SubItem "Elements"
//           of type "DTxxxxARR" (BaseType, ArrayInfo LBound 1, Elements n) at BitOffs 16.
// Values go into Object/Info/SubItem, one per sub-entry, matched by name.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "esi/model/dictionary.hpp"

namespace esi {

struct RecordEntry {
    DataTypeSubItem item;  // subindex, name, type, bit_size (0: implied by the type), flags …
    bool explicit_offset = false;  // keep item.bit_offset as given
    std::optional<ObjectInfo> info;  // DefaultValue, MinValue … of this entry
};

// The name "SubIndex 000" … CoE tools give unnamed sub-entries.
[[nodiscard]] std::string subindex_name(std::uint32_t subindex);

// A DataType name not yet used in the dictionary: `base`, else base_2, base_3 …
[[nodiscard]] std::string unique_type_name(const Dictionary& dictionary, const std::string& base);

// Bit size of a type name: basic types from the table, defined types from the dictionary; 0 when unknown.
[[nodiscard]] std::uint64_t type_bit_size(const Dictionary& dictionary, const std::string& type_name);

// Adds the DataType of a record and sets object.type, object.bit_size and the Info sub-items.
// Sub-index 0 ("SubIndex 000", USINT, value = highest sub-index) is added unless an entry gives it.
// Returns an error message (empty on success), e.g. when an entry's type has no known size.
[[nodiscard]] std::string build_record(Dictionary& dictionary, Object& object, const std::string& type_name,
                                       std::vector<RecordEntry> entries, const std::optional<ObjectFlags>& sub0_flags);

// Adds the DataTypes of an array of `count` elements (sub-indices 1..count) and sets the object's
// type, bit size and Info sub-items. `infos` holds count + 1 optional values (sub-index 0 first);
// sub-index 0 gets the element count when it has no value. `names` (optional, count + 1) names
// the sub-entries; an empty name means "SubIndex nnn".
[[nodiscard]] std::string build_array(Dictionary& dictionary, Object& object, const std::string& type_name,
                                      const std::string& element_type, std::uint32_t count,
                                      std::vector<std::optional<ObjectInfo>> infos,
                                      const std::optional<ObjectFlags>& sub0_flags,
                                      const std::optional<ObjectFlags>& element_flags,
                                      std::vector<std::string> names = {});

}  // namespace esi
