#pragma once
// The PDO entries of one owner (a device or a module) in the order of PdoScope::for_each_pdo,
// with what the pdo rules ask of each: what its DataType means and which object sub-entry it
// maps. Eight rules walk every entry of a catalogue; each answer is worked out once per entry and
// lint run (RuleCache::pdo_entries), where a lookup by entry would cost a hash per rule and entry.

#include <cstddef>
#include <vector>

#include "check/dictionary_index.hpp"
#include "check/pdo_entry_type.hpp"
#include "check/pdo_scope.hpp"

namespace esi::rules {

class PdoEntryFacts {
public:
    // `types` and `objects` are for the owner's Dictionary (or none) and must outlive this.
    PdoEntryFacts(const PdoScope& scope, EntryTypes& types, const DictionaryIndex& objects);

    [[nodiscard]] std::size_t size() const { return entries_.size(); }
    [[nodiscard]] const Pdo& pdo(std::size_t position) const { return *entries_[position].pdo; }
    [[nodiscard]] const PdoEntry& entry(std::size_t position) const { return *entries_[position].entry; }
    // What the entry's DataType means.
    [[nodiscard]] const EntryType& type(std::size_t position);
    // The object the entry maps (the first of its index); nullptr when the Dictionary has none.
    [[nodiscard]] const Object* object(std::size_t position);
    // The object sub-entry the entry maps; nullptr when the object or sub-index is missing.
    [[nodiscard]] const ObjectEntry* target(std::size_t position);

private:
    struct Known {
        const Pdo* pdo = nullptr;
        const PdoEntry* entry = nullptr;
        const EntryType* type = nullptr;  // null until asked for
        bool looked_up = false;           // object and target below are known
        const Object* object = nullptr;
        const ObjectEntry* target = nullptr;
    };
    Known& looked_up(std::size_t position);

    EntryTypes& types_;
    const DictionaryIndex& objects_;
    std::vector<Known> entries_;
};

}  // namespace esi::rules
