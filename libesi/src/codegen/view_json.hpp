#pragma once
// The view tree as JSON and back (esi-gen --dump-model, tests). Private to codegen: the public
// view header includes no third-party header.

#include <nlohmann/json.hpp>

#include "esi/codegen/view_tree.hpp"

namespace esi::codegen {

// The JSON the view stands for (what --dump-model prints): objects keep their member order,
// signed and unsigned integers stay apart as in nlohmann's number types.
[[nodiscard]] nlohmann::ordered_json to_json(const ViewValue& value);

// A view of a JSON document, for tests and tools that describe data as JSON.
[[nodiscard]] ViewValue from_json(ViewArena& arena, const nlohmann::ordered_json& json);

}  // namespace esi::codegen
