#pragma once
// Internal to the differ's comparison of object dictionaries, which is split in three files:
// compare_dictionary.cpp (objects, their defaults and limits, and the Dictionary as a whole),
// compare_data_types.cpp (DataTypes) and compare_entry_values.cpp (an entry's value and access
// as a master sees them, shared by objects and DataType SubItems).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "diff/compare.hpp"
#include "esi/data_types.hpp"

namespace esi::diff_detail {

// The default (or a limit) of an entry as the bytes a master would read, little-endian as CoE
// transfers them (ETG.1000.6), plus how to show it.
struct EntryValue {
    bool present = false;
    std::optional<std::vector<std::uint8_t>> bytes;  // absent for undecodable data
    std::string raw;                                 // compared when bytes are absent
    std::string display;
    std::optional<Number> number;  // for ordering limits
};

// A default, minimum or maximum given as a number, hex data or a string (at most one of them).
EntryValue value_of(const std::optional<Number>& number, const std::optional<HexData>& data,
                    const std::optional<std::string>& string, std::uint64_t bit_size, const BasicType* basic, bool as_hex);

// Same bytes (or, for undecodable data, the same text).
bool same_value(const EntryValue& a, const EntryValue& b);

// The Flags of an entry: Access with its restrictions (narrowed, widened or only respelled),
// PdoMapping and SafetyMapping (letters added or removed), and the other flags as text.
void compare_flags(Recorder& r, const std::string& p, const ObjectFlags* a, const ObjectFlags* b, SourcePos pa, SourcePos pb);

// DataTypes pair up by canonical name.
void compare_data_types(Recorder& r, const std::string& path, const Dictionary* a, const Dictionary* b, SourcePos old_parent,
                        SourcePos new_parent);

}  // namespace esi::diff_detail
