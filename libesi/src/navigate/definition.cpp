// Go to definition and find references: both start from the occurrence under the cursor and
// stay within its device (or module).

#include "navigate/index.hpp"

namespace esi::navigate {

namespace {

const Occurrence* occurrence_at(const Index& index, Position position) {
    const auto offset = index.lines.offset_of(position);
    if (!offset) return nullptr;
    return index.occurrence_at(*offset);
}

}  // namespace

std::vector<Location> definition(const Index& index, Position position) {
    const Occurrence* occurrence = occurrence_at(index, position);
    if (!occurrence) return {};
    const auto target = index.definition_of(*occurrence);
    if (!target) return {};
    return {index.location(*target)};
}

std::vector<Location> references(const Index& index, Position position, bool include_declaration) {
    const Occurrence* occurrence = occurrence_at(index, position);
    if (!occurrence) return {};
    std::vector<Location> found;
    // Occurrences are in document order, so the locations are too.
    for (const Occurrence& other : index.occurrences) {
        if (!index.same_target(*occurrence, other)) continue;
        if (other.declaration && !include_declaration) continue;
        found.push_back(index.location(other.span));
    }
    return found;
}

}  // namespace esi::navigate
