#pragma once
// Default, minimum and maximum values of one object sub-entry, decoded the way the entry's data
// type reads them. Where a value comes from (ETG.2000 ObjectInfoType / SubItemType):
// DefaultValue/MinValue/MaxValue (a HexDecValue), DefaultData/MinData/MaxData (hexBinary, the
// value's bytes little-endian as they go over SDO) or DefaultString; the object's Info wins over
// the DataType SubItem's values. Generated code spells them as literals (codegen/values.hpp),
// esi-doc's dictionary tables as text.

#include <cstdint>
#include <string>

#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::codegen {

// How generated code holds an entry's value.
enum class ValueClass { signed_integer, unsigned_integer, real, string, bytes };

[[nodiscard]] ValueClass value_class_of(const BasicType* basic);

struct DecodedValue {
    enum class Kind { none, signed_integer, unsigned_integer, real, string, bytes };
    Kind kind = Kind::none;
    std::int64_t i = 0;
    std::uint64_t bits = 0;  // integer: two's complement truncated to the bit length; real: IEEE bits
    double r = 0.0;
    std::string text;  // string or raw bytes
};

// The three values of an entry (none present = Kind::none).
struct EntryValues {
    DecodedValue default_value;
    DecodedValue min;
    DecodedValue max;
};

[[nodiscard]] EntryValues decode_entry_values(const ObjectEntry& entry);

}  // namespace esi::codegen
