#pragma once
// Type names written in a YAML device source (`type: UINT`). A name that is neither a basic type,
// STRING(n), an ARRAY form nor a data type declared in the same dictionary, but is a common
// non-standard spelling or close to a basic type's name, is a misspelling ("UNIT" for "UINT",
// "UINT16" for "UINT"). It is reported at the type with the name meant, before it can surface
// further on as a misleading size or value error. A name close to nothing is left alone: a
// module's objects may use a type the device declares.

#include <string>
#include <string_view>

#include "esi/model/dictionary.hpp"

namespace esi::yaml {

// "unknown type 'UNIT'; did you mean 'UINT'? (…)"; empty when `type` is known in `dictionary`
// or not a misspelt basic type.
[[nodiscard]] std::string misspelt_type_message(std::string_view type, const Dictionary& dictionary);

}  // namespace esi::yaml
