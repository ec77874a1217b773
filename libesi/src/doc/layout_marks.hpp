#pragma once
// What changed between two bit layouts of the same thing (a PDO, a SyncManager image), entry by
// entry: an entry is the same entry on both sides when it maps the same object index and
// sub-index (the n-th mapping of it on one side pairs with the n-th on the other). Padding is
// not paired: it moves with what is around it.

#include <vector>

#include "esi/doc/bit_layout.hpp"

namespace esi::doc {

// Marks the fields of both sides: only old, removed; only new, added; another size, resized; the
// same size at another offset, moved.
void mark_changes(std::vector<LayoutField>& old_fields, std::vector<LayoutField>& new_fields);

// Both sides hold the same entries at the same offsets with the same sizes, types and names.
[[nodiscard]] bool same_layout(const std::vector<LayoutField>& a, const std::vector<LayoutField>& b);

}  // namespace esi::doc
