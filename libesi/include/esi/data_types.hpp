#pragma once
// The one data-type table of the library: ESI name <-> CoE code <-> bit size <-> signedness
// (ETG.1000.6 / CiA 301 codes; ESI names as in Beckhoff ET9300 Table 22). Every pass (lint,
// generators, SII, diff) asks this table; nothing else hard-codes a type size.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace esi {

enum class TypeClass {
    boolean,           // BOOL
    bit,               // BIT1..BIT16: unsigned bit fields
    signed_integer,    // SINT, INT, INT24, DINT, INT40..LINT
    unsigned_integer,  // USINT, UINT, UINT24, UDINT, UINT40..ULINT
    real,              // REAL, LREAL
    bit_string,        // BYTE, WORD, DWORD, BITARR8/16/32: raw bits, no arithmetic sign
    visible_string,    // STRING(n)
    octet_string,      // OCTET_STRING / ARRAY OF BYTE
    unicode_string,
    time,              // TIME_OF_DAY, TIME_DIFFERENCE
    domain,            // DOMAIN: no fixed size
    guid,
    structured,        // PDO_MAPPING, IDENTITY, RECORD ...: defined by a DataType element
};

struct BasicType {
    std::string_view esi_name;  // "UINT"
    std::string_view coe_name;  // "UNSIGNED16"
    std::uint16_t coe_code;     // 0x0006
    std::uint32_t bit_size;     // 16; 0 = variable or defined by a DataType element
    TypeClass type_class;

    [[nodiscard]] constexpr bool is_signed() const {
        return type_class == TypeClass::signed_integer || type_class == TypeClass::real;
    }
    [[nodiscard]] constexpr bool is_integer() const {
        return type_class == TypeClass::signed_integer || type_class == TypeClass::unsigned_integer ||
               type_class == TypeClass::bit || type_class == TypeClass::boolean || type_class == TypeClass::bit_string;
    }
};

// All basic types, ordered by CoE code.
[[nodiscard]] std::span<const BasicType> basic_types();
// Exact ESI name ("UINT", "BIT3", "BITARR16"); nullptr when unknown.
[[nodiscard]] const BasicType* find_basic_type(std::string_view esi_name);
// CoE name ("UNSIGNED16"); nullptr when unknown.
[[nodiscard]] const BasicType* find_basic_type_by_coe_name(std::string_view coe_name);
[[nodiscard]] const BasicType* find_basic_type_by_code(std::uint16_t coe_code);

// The standard ESI name a common non-standard spelling means ("UINT16" -> "UINT",
// "BOOLEAN" -> "BOOL", "UNSIGNED32" -> "UDINT"); empty when there is no such spelling.
[[nodiscard]] std::string_view standard_type_name_for(std::string_view nonstandard);

// A DataType/Type text taken apart.
struct TypeName {
    enum class Kind { basic, string, array, named };
    Kind kind = Kind::named;
    const BasicType* basic = nullptr;   // basic: the type; array: the element type when basic
    std::uint32_t string_length = 0;    // STRING(n)
    std::int64_t lower_bound = 0;       // ARRAY [lower..upper] OF element
    std::int64_t upper_bound = -1;
    std::string element;                // array element type name, as written
    std::string name;                   // named: the text (e.g. "DT1018")

    [[nodiscard]] std::uint64_t element_count() const {
        return upper_bound >= lower_bound ? static_cast<std::uint64_t>(upper_bound - lower_bound) + 1u : 0u;
    }
};

// Parses "UINT", "STRING(10)", "ARRAY [0..3] OF BYTE", "DT1018" (whitespace tolerant).
// Never fails: anything that is not basic, string or array is `named`.
[[nodiscard]] TypeName parse_type_name(std::string_view text);

// Bit size implied by the name alone (basic types, STRING(n), arrays of basic types);
// nullopt for named types and variable-size types.
[[nodiscard]] std::optional<std::uint64_t> implied_bit_size(std::string_view type_name);

// Canonical spelling, used to compare type names across files: "ARRAY [0..3] OF BYTE".
[[nodiscard]] std::string canonical_type_name(std::string_view type_name);

}  // namespace esi
