#pragma once
// A value written in a source (an object default, an InitCmd value) before the type that gives
// it meaning is known, and its encoding once it is: CoE transfers numbers little-endian in the
// object's size (ETG.1000.6 5.6.2; STÖBER manual §7.2.2 "Intel-Format … Little-endian"), so the
// value 8 for a SINT object is the one byte 08 and 0x1600 for a UINT is 00 16.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "esi/data_types.hpp"
#include "esi/model/dictionary.hpp"
#include "esi/number.hpp"
#include "esi/source_pos.hpp"

namespace esi {

struct SourceValue {
    enum class Kind { integer, real, boolean, text };
    Kind kind = Kind::text;
    Number integer;
    double real = 0;
    bool boolean = false;
    std::string text;  // the value as written (every kind)
    SourcePos pos;
};

struct EncodedValue {
    std::vector<std::uint8_t> bytes;
    std::string error;  // why the value does not fit the type; empty when it does
    [[nodiscard]] bool ok() const { return error.empty(); }
};

// The type a value is checked against: a basic type, its size (STRING(n), BITn …) and, for
// enumerations, the DataType whose EnumInfo texts may be used instead of numbers.
struct ValueType {
    const BasicType* basic = nullptr;
    std::uint64_t bit_size = 0;
    std::string name;                  // as the object or sub-item names it, for messages
    const DataType* enumeration = nullptr;
};

// Integer-like types (BOOL, BITn, SINT … ULINT, BYTE … DWORD, BITARRn): the value as a Number
// after range checks; an enumeration text is replaced by its value.
[[nodiscard]] std::optional<Number> integer_value(const SourceValue& value, const ValueType& type, std::string& error);

// The bytes CoE would transfer: integers and enums little-endian in ceil(bits/8) bytes, REAL and
// LREAL as IEEE 754 little-endian, STRING(n) as its characters (at most n).
[[nodiscard]] EncodedValue encode_value(const SourceValue& value, const ValueType& type);

}  // namespace esi
