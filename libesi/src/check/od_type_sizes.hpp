#pragma once
// The BitSize of a Dictionary's DataTypes judged the way their users see them. An array type's
// BitSize should be Elements times its BaseType's size (ETG.2000 ArrayInfo), but two conventions
// of real dictionaries differ from that and are consistent once the users are looked at:
//   - SoE lists (IEC 61800-7-204 list format, carried by SoE): the list record is a 16-bit
//     current length, a 16-bit maximum length and the elements; Beckhoff's AX5 dictionaries give
//     the element array the BitSize of the whole record (25 x 16 + 32 = 432 bits) while the
//     record's SubItem "Elements" declares the elements alone (400);
//   - arrays of BOOL/BITn take whole bytes (5 BOOL in 8 bits).
// od-array-size reports an array whose size neither adds up nor fits a convention; od-bitsize
// leaves a user's size to od-array-size and od-subitem-layout where the type's own BitSize is
// the cause, so that each cause is one finding.

#include <cstdint>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "check/od_type_index.hpp"
#include "esi/model/dictionary.hpp"

namespace esi::rules {

enum class ArrayFit {
    not_an_array,  // no ArrayInfo, or nothing to compare (no BitSize, BaseType of unknown size)
    negative,      // an Elements below 0 (reported as such)
    consistent,    // BitSize = Elements x BaseType size
    soe_list,      // BitSize = that + 32, the size of the enclosing SoE list record
    whole_bytes,   // BOOL/BITn elements rounded up to whole bytes
    mismatch,      // none of these
};

struct ArraySize {
    ArrayFit fit = ArrayFit::not_an_array;
    std::uint64_t elements = 0;
    std::uint64_t element_bits = 0;
    const ArrayInfo* negative = nullptr;  // the ArrayInfo with Elements < 0
};

class DataTypeSizes {
public:
    // `types` indexes the same Dictionary and must outlive this.
    DataTypeSizes(const Dictionary& dictionary, const TypeIndex& types);

    [[nodiscard]] const ArraySize& array(const DataType& type) const;
    // Whether a user (SubItem or Object) whose BitSize differs from this type's is explained by
    // the type's own BitSize: a convention above, or a fault od-array-size or od-subitem-layout
    // reports about the type itself.
    [[nodiscard]] bool own_size_accounts_for_users(const DataType& type) const;

private:
    struct Use {
        const DataTypeSubItem* item = nullptr;  // a SubItem of `owner`, or null for an Object
        const DataType* owner = nullptr;
        std::uint64_t bit_size = 0;
    };
    [[nodiscard]] ArraySize judge(const DataType& type);
    [[nodiscard]] bool used_as_soe_list(const DataType& type, std::uint64_t element_data_bits);

    const Dictionary& dictionary_;
    const TypeIndex& types_;
    // The SubItems and Objects by the type name they use, built when the first array could be an
    // SoE list (only SoE dictionaries have such arrays; others never pay for the map).
    std::unordered_map<std::string_view, std::vector<Use>> users_;
    bool users_built_ = false;
    std::unordered_map<const DataType*, ArraySize> arrays_;
};

}  // namespace esi::rules
