#include "check/pdo_entry_facts.hpp"

namespace esi::rules {

PdoEntryFacts::PdoEntryFacts(const PdoScope& scope, EntryTypes& types, const DictionaryIndex& objects) : types_(types), objects_(objects) {
    std::size_t count = 0;
    scope.for_each_pdo([&](const Pdo& pdo) { count += pdo.entries.size(); });
    entries_.reserve(count);
    scope.for_each_pdo([&](const Pdo& pdo) {
        for (const auto& entry : pdo.entries) entries_.push_back(Known{.pdo = &pdo, .entry = &entry});
    });
}

const EntryType& PdoEntryFacts::type(std::size_t position) {
    Known& known = entries_[position];
    if (!known.type) known.type = &types_.of(*known.entry);  // EntryTypes keeps its answers in place
    return *known.type;
}

PdoEntryFacts::Known& PdoEntryFacts::looked_up(std::size_t position) {
    Known& known = entries_[position];
    if (!known.looked_up) {
        // Neighbouring entries mostly map sub-indices of one object (0x6000:01, 0x6000:02 …).
        const Known* before = position > 0 ? &entries_[position - 1] : nullptr;
        known.object = before && before->looked_up && before->entry->index == known.entry->index ? before->object
                                                                                                 : objects_.object(known.entry->index);
        known.target = known.object ? objects_.layout(*known.object).entry(known.entry->effective_subindex()) : nullptr;
        known.looked_up = true;
    }
    return known;
}

const Object* PdoEntryFacts::object(std::size_t position) { return looked_up(position).object; }

const ObjectEntry* PdoEntryFacts::target(std::size_t position) { return looked_up(position).target; }

}  // namespace esi::rules
