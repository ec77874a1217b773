#include "check/dictionary_index.hpp"

#include <algorithm>

namespace esi::rules {

namespace {
bool index_less(const std::pair<std::uint32_t, const Object*>& a, const std::pair<std::uint32_t, const Object*>& b) {
    return a.first < b.first;
}

// The number of DataTypes up to which layouts scan the list (measured on the corpus: a scan of up
// to 64 names costs no more than building the index and asking it; a few catalogues define
// hundreds).
constexpr std::size_t scanned_data_types = 64;
}  // namespace

DictionaryIndex::DictionaryIndex(const Dictionary* dictionary) : dictionary_(dictionary) {
    if (!dictionary) return;
    if (dictionary->data_types.size() > scanned_data_types) types_.emplace(dictionary);
    by_index_.reserve(dictionary->objects.size());
    for (const auto& o : dictionary->objects) by_index_.emplace_back(o.index, &o);
    // Dictionaries list their objects by index as a rule; the stable sort is for those that do not.
    if (!std::is_sorted(by_index_.begin(), by_index_.end(), index_less)) std::stable_sort(by_index_.begin(), by_index_.end(), index_less);
    layouts_.resize(dictionary->objects.size());
}

const Object* DictionaryIndex::object(std::uint32_t index) const {
    const auto it = std::lower_bound(by_index_.begin(), by_index_.end(), std::pair<std::uint32_t, const Object*>{index, nullptr}, index_less);
    return it != by_index_.end() && it->first == index ? it->second : nullptr;
}

const ObjectLayout* DictionaryIndex::layout(std::uint32_t index) const {
    const Object* o = object(index);
    return o ? &layout(*o) : nullptr;
}

const ObjectLayout& DictionaryIndex::layout(const Object& object) const {
    std::optional<ObjectLayout>& slot = layouts_[static_cast<std::size_t>(&object - dictionary_->objects.data())];
    if (!slot) slot = types_ ? layout_of(*types_, object) : layout_of(dictionary_, object);
    return *slot;
}

const ObjectEntry* DictionaryIndex::entry(std::uint32_t index, std::uint32_t subindex) const {
    const ObjectLayout* l = layout(index);
    return l ? l->entry(subindex) : nullptr;
}

}  // namespace esi::rules
