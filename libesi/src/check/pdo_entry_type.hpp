#pragma once
// What a PDO entry's DataType text means: a basic type, STRING(n), an array, or a type the
// owner's Dictionary defines (DataTypes); with its size in bits.

#include <cstdint>
#include <string_view>
#include <unordered_map>

#include "esi/data_types.hpp"
#include "esi/model/dictionary.hpp"
#include "esi/model/pdo.hpp"
#include "check/last_name_answer.hpp"
#include "check/od_type_index.hpp"

namespace esi::rules {

struct EntryType {
    bool present = false;                // a non-empty DataType is written
    bool known = false;                  // it resolves (basic, STRING(n), array or defined), a known
                                         // non-standard spelling as the type it stands for
    const BasicType* basic = nullptr;    // the basic type it ends in, if any
    std::uint64_t bit_size = 0;          // 0 when unknown or variable
    std::string_view nonstandard_name;   // the undefined non-standard spelling (UINT16), also inside ARRAY … OF
    std::string_view standard_name;      // and the standard name it stands for (UINT)
};

[[nodiscard]] EntryType entry_type(const TypeIndex& types, const PdoEntry& entry);

// entry_type() remembered per DataType text: four pdo rules ask it of every entry, and a
// catalogue writes a handful of type names thousands of times (each answer needs several
// lookups and type-name parses). Used on one thread; the model must outlive it unchanged.
class EntryTypes {
public:
    explicit EntryTypes(const TypeIndex& types) : types_(types) {}
    [[nodiscard]] const TypeIndex& types() const { return types_; }
    [[nodiscard]] const EntryType& of(const PdoEntry& entry);

private:
    const TypeIndex& types_;
    EntryType absent_;  // no DataType element
    std::unordered_map<std::string_view, EntryType> by_text_;
    // Neighbouring entries mostly share a DataType (a PDO of eight BOOL inputs): a comparison
    // with the text asked last spares the hash of it.
    LastNameAnswer<const EntryType*> last_;
};

}  // namespace esi::rules
