#pragma once
// The DataTypes of one Dictionary by exact name, the first of each name (as DataTypeIndex::find
// answers), for the rules' type index. The od rules look up a type name for every Object,
// SubItem and BaseType, tens of thousands per catalogue: here a lookup is a short hash of the
// name and a probe of one array, where DataTypeIndex first asks the basic-type table and then
// hashes the name into a map of nodes.

#include <cstddef>
#include <string_view>
#include <vector>

#include "esi/model/dictionary.hpp"

namespace esi::rules {

class DataTypeNames {
public:
    // A null Dictionary has no DataTypes.
    explicit DataTypeNames(const Dictionary* dictionary);
    // The first DataType of exactly that name; nullptr when none.
    [[nodiscard]] const DataType* find(std::string_view name) const;
    // Whether `type` (of this Dictionary) is what find(type.name) answers: the first of its name.
    [[nodiscard]] bool is_first_of_name(const DataType& type) const;

private:
    struct Slot {
        std::string_view name;
        const DataType* type = nullptr;  // null: an empty slot
    };
    [[nodiscard]] std::size_t home(std::string_view name) const;

    const Dictionary* dictionary_;
    // Open addressing with linear probing; at most half the slots are used, so that a search
    // ends at an empty slot after a probe or two. The size is a power of two.
    std::vector<Slot> slots_;
    std::vector<bool> first_of_name_;  // by position in DataTypes, noted while the slots are filled
};

}  // namespace esi::rules
