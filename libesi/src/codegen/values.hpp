#pragma once
// Default, minimum and maximum values of one object sub-entry, decoded the way the entry's data
// type reads them, and spelled as C/C++ literals for the templates.
//
// Where a value comes from (ETG.2000 ObjectInfoType / SubItemType): DefaultValue/MinValue/MaxValue
// (a HexDecValue), DefaultData/MinData/MaxData (hexBinary, the value's bytes little-endian as they
// go over SDO) or DefaultString. The object's Info wins over the DataType
// SubItem's values.

#include <cstdint>
#include <optional>
#include <string>

#include "esi/codegen/view_tree.hpp"
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

// The value view documented in docs/codegen.md ("Value").
[[nodiscard]] ViewValue value_view(ViewArena& arena, const DecodedValue& value, std::uint64_t bit_length);

// Whether the value carries bits (integers and reals), and its low 32 bits as the value view's
// `bits32_hex` spells them (for SOES's 32-bit default field).
[[nodiscard]] bool has_bits(const DecodedValue& value);
[[nodiscard]] bool fits_32_bits(const DecodedValue& value);

// Short text in a fixed buffer (hex numbers, small literals): no heap allocation.
struct ShortText {
    char data[32];
    std::uint8_t size = 0;
    operator std::string_view() const { return {data, size}; }  // NOLINT: converts like a string
    [[nodiscard]] std::string str() const { return {data, size}; }
};

// "0x" + upper-case hex digits, at least `digits` of them (at most 16 are needed).
[[nodiscard]] ShortText hex_text(std::uint64_t value, int digits);
[[nodiscard]] inline std::string hex(std::uint64_t value, int digits) { return hex_text(value, digits).str(); }
// `digits` upper-case hex digits without "0x" ("1A00" for the index of a mapping object).
[[nodiscard]] ShortText plain_hex_text(std::uint64_t value, int digits);
[[nodiscard]] ShortText bits32_hex(const DecodedValue& value, std::uint64_t bit_length);

}  // namespace esi::codegen
