#pragma once
// Narrowing a comparison to the classes a reader cares about (esi-diff --ignore cosmetic,
// --only breaking): the changes of the other classes are dropped and the verdict is that of what
// is left, so --fail-on and the summary agree with the report.

#include <set>

#include "esi/diff/diff.hpp"

namespace esi {

// Keeps the changes whose class is in `classes`; the verdict becomes the most severe class kept
// (identical when none is).
void keep_classes(DiffResult& result, const std::set<ChangeClass>& classes);

// "cosmetic", "compatible", "breaking" -> the class; nullopt for anything else.
[[nodiscard]] std::optional<ChangeClass> change_class_named(std::string_view name);

}  // namespace esi
