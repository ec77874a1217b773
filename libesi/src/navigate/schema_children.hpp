#pragma once
// The child elements ETG.2000 (EtherCATInfo.xsd 1.17, EtherCATBase.xsd) allows under an element,
// in schema order: what element-name completion offers at the cursor.

#include <span>
#include <string_view>

namespace esi::navigate {

// Children of `parent` (whose own parent is `grandparent`, which tells apart elements of one
// name in two places: Object/Info vs Device/Info, DataType/SubItem vs Info/SubItem, Device/Sm vs
// OpMode/Sm). Empty for an element of simple content or one the table does not know.
[[nodiscard]] std::span<const std::string_view> schema_children(std::string_view parent, std::string_view grandparent);

}  // namespace esi::navigate
