#pragma once
// Values of dictionary entries as numbers. ETG.2000 ObjectInfoType: DefaultData, MinData and
// MaxData hold the value's bytes as an SDO transfers them, little-endian (Beckhoff writes the PDO
// index 0x1A00 as "001a"); DefaultValue, MinValue and MaxValue are HexDecValues. Vendors write
// limits of signed objects as bit patterns (MinValue #xfff80001 for a DINT), so values of signed
// entries are read as two's complement of the entry's width when they only fit that way.

#include <cstdint>
#include <optional>

#include "esi/model/common.hpp"
#include "esi/model/dictionary.hpp"
#include "esi/number.hpp"

namespace esi::rules {

// How to read the values of one entry: its width and signedness.
struct ValueFormat {
    std::uint64_t bit_size = 0;  // 1..64
    bool is_signed = false;
};

// The bit pattern a little-endian byte string holds (ETG.2000 DefaultData is in SDO order).
// nullopt when the data is not valid hex, empty or longer than 8 bytes. Read in place, without
// allocating (unlike HexData::bytes()): rules read every default, minimum and maximum of the
// dictionaries.
[[nodiscard]] std::optional<std::uint64_t> little_endian_pattern(const HexData& data);

// The integer a little-endian byte string holds, sign-extended for signed formats. nullopt when
// the data is not valid hex, empty or longer than 8 bytes.
[[nodiscard]] std::optional<Number> number_from_data(const HexData& data, const ValueFormat& format);

// A HexDecValue as the entry means it: non-negative values of a signed entry that only fit as a
// bit pattern of the entry's width are taken as two's complement.
[[nodiscard]] Number normalized(const Number& value, const ValueFormat& format);

// A value given as a HexDecValue or as data (the value wins). nullopt when absent or unreadable.
[[nodiscard]] std::optional<Number> value_of(const std::optional<Number>& value, const std::optional<HexData>& data,
                                             const ValueFormat& format);
// DefaultValue, else DefaultData (and the same for Min/Max). nullopt when absent or unreadable.
[[nodiscard]] std::optional<Number> default_number(const ObjectInfo& info, const ValueFormat& format);
[[nodiscard]] std::optional<Number> min_number(const ObjectInfo& info, const ValueFormat& format);
[[nodiscard]] std::optional<Number> max_number(const ObjectInfo& info, const ValueFormat& format);

// The smallest and largest value of a format.
[[nodiscard]] Number format_min(const ValueFormat& format);
[[nodiscard]] Number format_max(const ValueFormat& format);

// a < b for signed 65-bit numbers.
[[nodiscard]] bool less(const Number& a, const Number& b);

}  // namespace esi::rules
