#pragma once
// The objects of one Dictionary by index, and their layouts, each computed once: dictionaries
// reach thousands of objects, and many rules ask for the same objects and layouts (see
// RuleCache, which holds one index per Dictionary and lint run).

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "esi/model/dictionary.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::rules {

class DictionaryIndex {
public:
    explicit DictionaryIndex(const Dictionary* dictionary);
    [[nodiscard]] const Dictionary* dictionary() const { return dictionary_; }
    // The first object with that index.
    [[nodiscard]] const Object* object(std::uint32_t index) const;
    // The sub-entry a PDO entry or InitCmd addresses; nullptr when the object or sub-index is missing.
    [[nodiscard]] const ObjectEntry* entry(std::uint32_t index, std::uint32_t subindex) const;
    [[nodiscard]] const ObjectLayout* layout(std::uint32_t index) const;
    // The layout of an object of this Dictionary (duplicates of an index included); `object`
    // must be an element of its Objects.
    [[nodiscard]] const ObjectLayout& layout(const Object& object) const;

private:
    const Dictionary* dictionary_;
    // Layouts look type names up in the DataTypes. Nearly all Dictionaries define a few dozen at
    // most, and layout_of scans such a list faster (names of another length are passed over at
    // once) than a DataTypeIndex, with a map node per DataType, is built and asked; only a longer
    // list gets the index.
    std::optional<DataTypeIndex> types_;
    // The objects' indices with the objects, sorted by index and, among equal indices, in the
    // order of the Dictionary: a binary search finds the first object of an index.
    std::vector<std::pair<std::uint32_t, const Object*>> by_index_;
    // Layouts by the object's position in the Dictionary's Objects, each built when first asked
    // for. Sized once, so the references handed out stay valid.
    mutable std::vector<std::optional<ObjectLayout>> layouts_;
};

}  // namespace esi::rules
