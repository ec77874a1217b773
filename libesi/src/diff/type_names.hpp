#pragma once
// Internal to the differ: how two type names compare. Names are compared canonically
// ("ARRAY[0..3] OF BYTE" = "ARRAY [0..3] OF BYTE"); a common alias of a standard name
// ("UINT16" for "UINT") means the same type but is a spelling change; with dictionaries, two
// differently named DataTypes with the same layout are a rename, not a type change.

#include <string>
#include <string_view>

#include "esi/model/dictionary.hpp"

namespace esi::diff_detail {

enum class TypeMatch { same, spelling, different };

// The canonical name with common aliases replaced by the standard ESI name.
[[nodiscard]] std::string normalized_type_name(std::string_view name);

// Names only (PDO entries: their layout is given by BitLen).
[[nodiscard]] TypeMatch compare_type_names(std::string_view old_name, std::string_view new_name);

// Names resolved in their dictionaries: bit size, basic type, array bounds and structure compared.
[[nodiscard]] TypeMatch compare_types(const Dictionary* old_dictionary, std::string_view old_name,
                                      const Dictionary* new_dictionary, std::string_view new_name);

}  // namespace esi::diff_detail
