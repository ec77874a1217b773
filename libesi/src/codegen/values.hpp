#pragma once
// Entry values (esi/codegen/entry_values.hpp: decoded from the file) spelled as C/C++ literals
// for the templates.

#include <cstdint>
#include <optional>
#include <string>

#include "esi/codegen/entry_values.hpp"
#include "esi/codegen/view_tree.hpp"
#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::codegen {

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
