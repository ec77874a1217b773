#pragma once
// What a PDO entry's DataType text means: a basic type, STRING(n), an array, or a type the
// owner's Dictionary defines (DataTypes); with its size in bits.

#include <cstdint>
#include <string_view>

#include "esi/data_types.hpp"
#include "esi/model/dictionary.hpp"
#include "esi/model/pdo.hpp"
#include "check/od_type_index.hpp"

namespace esi::rules {

struct EntryType {
    bool present = false;                // a non-empty DataType is written
    bool known = false;                  // it resolves (basic, STRING(n), array or defined)
    const BasicType* basic = nullptr;    // the basic type it ends in, if any
    std::uint64_t bit_size = 0;          // 0 when unknown or variable
    std::string_view nonstandard_name;   // the undefined non-standard spelling (UINT16), also inside ARRAY … OF
    std::string_view standard_name;      // and the standard name it stands for (UINT)
};

[[nodiscard]] EntryType entry_type(const TypeIndex& types, const PdoEntry& entry);

}  // namespace esi::rules
