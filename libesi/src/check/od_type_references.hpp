#pragma once
// The places where a Dictionary names a type (an Object's Type, a SubItem's Type, a BaseType),
// with what each name means. od-type-unresolved, od-nonstandard-type-name and od-bitsize judge
// the same references: the names are looked up once (RuleCache::referenced_types) and each rule
// takes what it needs.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "check/od_type_index.hpp"
#include "esi/model/dictionary.hpp"
#include "esi/number.hpp"

namespace esi::rules {

struct TypeReference {
    std::string_view name;  // trimmed
    SourcePos pos;
    const Object* object = nullptr;
    const DataType* data_type = nullptr;
    const DataTypeSubItem* sub_item = nullptr;
};

// Calls f(TypeReference) for every non-empty type name of the Dictionary: BaseTypes and SubItem
// types of each DataType, then the Objects' types, in the order of the file.
template <class F>
void for_each_type_reference(const Dictionary& dictionary, F&& f) {
    for (const auto& type : dictionary.data_types) {
        if (type.base_type)
            if (const std::string_view base = trim(*type.base_type); !base.empty()) f(TypeReference{base, type.pos, nullptr, &type, nullptr});
        for (const auto& item : type.sub_items)
            if (const std::string_view name = trim(item.type); !name.empty()) f(TypeReference{name, item.pos, nullptr, &type, &item});
    }
    for (const auto& object : dictionary.objects)
        if (const std::string_view name = trim(object.type); !name.empty())
            f(TypeReference{name, object.type_pos.line ? object.type_pos : object.pos, &object, nullptr, nullptr});
}

// A reference with what its name means: whether it resolves (TypeIndex::status, with the part of
// the name at fault) and its size in bits (TypeIndex::bit_size).
struct ReferencedType {
    TypeReference reference;
    TypeNameStatus status = TypeNameStatus::resolved;
    std::string_view culprit;
    std::optional<std::uint64_t> bit_size;
};

// Every reference of a Dictionary, in the order of for_each_type_reference.
[[nodiscard]] std::vector<ReferencedType> referenced_types(const Dictionary& dictionary, const TypeIndex& types);

}  // namespace esi::rules
