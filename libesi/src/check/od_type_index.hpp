#pragma once
// The DataTypes of one Dictionary by name, for the od-… type checks: what a type name refers
// to and how many bits it has, without re-scanning the DataTypes list for every reference
// (Beckhoff dictionaries define hundreds of types).

#include <cstdint>
#include <optional>
#include <string_view>
#include <unordered_set>

#include "check/data_type_names.hpp"
#include "esi/data_types.hpp"
#include "esi/model/dictionary.hpp"

namespace esi::rules {

enum class TypeNameStatus {
    resolved,     // a basic type, STRING(n), an array of a resolvable type, or a defined DataType
    nonstandard,  // undefined, but a known non-standard spelling of a basic type (UINT16)
    unresolved,   // nothing it could refer to
};

class TypeIndex {
public:
    explicit TypeIndex(const Dictionary& dictionary);
    // For owners without a Dictionary: only basic types, STRING(n) and arrays of them resolve.
    explicit TypeIndex(const Dictionary* dictionary);

    // The first DataType of that name (as ETG.2000's DataTypeKey would have it unique).
    [[nodiscard]] const DataType* find(std::string_view name) const;
    // For arrays ("ARRAY [0..3] OF X") the element name decides; `culprit` is set to the part
    // of the name that does not resolve.
    [[nodiscard]] TypeNameStatus status(std::string_view name, std::string_view* culprit = nullptr) const;
    // Bits of a type: a DataType's BitSize, else what the name implies; nullopt when unknown.
    [[nodiscard]] std::optional<std::uint64_t> bit_size(std::string_view name) const;
    // status() and bit_size() of one name together, for walks over every type reference: the
    // two share their look-ups.
    struct NameFacts {
        TypeNameStatus status = TypeNameStatus::resolved;
        std::string_view culprit;  // as status() gives it
        std::optional<std::uint64_t> bit_size;
    };
    [[nodiscard]] NameFacts facts(std::string_view name) const;
    // The basic type a name ends in, following BaseType (an enum DT0800EN03 based on USINT is
    // USINT); nullptr for arrays, structures and unresolved names.
    [[nodiscard]] const BasicType* basic(std::string_view name) const;
    // Whether following BaseType from this DataType comes back to it.
    [[nodiscard]] bool in_base_type_cycle(const DataType& type) const;
    // Whether `type` (of this Dictionary) is the one find(type.name) answers, the first of its
    // name; later ones are duplicates. Known for every DataType once the index is built.
    [[nodiscard]] bool is_first_of_name(const DataType& type) const;

private:
    void find_cycles(const Dictionary& dictionary);

    DataTypeNames names_;
    std::unordered_set<const DataType*> in_cycle_;
};

}  // namespace esi::rules
