#pragma once
// What several rules compute about the same Dictionary, computed once per lint run: its
// DataTypes by name (with BaseType loops), its objects by index and their layouts, the type
// references whose names do not resolve. Rules take these from the cache (RuleContext::cache)
// and never build their own, so each index and each object layout is built at most once per
// Dictionary and run, however many rules ask.
//
// A cache belongs to one run of the rules over one document (run_rules) on one thread; the
// model must not change while it lives.

#include <memory>
#include <unordered_map>

#include "check/od_type_index.hpp"
#include "check/od_type_references.hpp"
#include "check/od_type_sizes.hpp"
#include "check/pdo_entry_type.hpp"
#include "check/queries.hpp"

namespace esi::rules {

class RuleCache {
public:
    // A null Dictionary gives the index of an owner without one: only basic types resolve.
    [[nodiscard]] const TypeIndex& types(const Dictionary* dictionary);
    [[nodiscard]] const DictionaryIndex& objects(const Dictionary* dictionary);
    // What PDO entries' DataTypes mean for an owner with this Dictionary (or none).
    [[nodiscard]] EntryTypes& entry_types(const Dictionary* dictionary);
    // The DataTypes' sizes as their users see them (a Dictionary, not null).
    [[nodiscard]] const DataTypeSizes& type_sizes(const Dictionary& dictionary);
    // The type references whose names do not resolve (a Dictionary, not null).
    [[nodiscard]] const std::vector<TypeReferenceFault>& type_reference_faults(const Dictionary& dictionary);

private:
    struct PerDictionary {
        std::unique_ptr<TypeIndex> types;
        std::unique_ptr<DictionaryIndex> objects;
        std::unique_ptr<EntryTypes> entry_types;
        std::unique_ptr<DataTypeSizes> type_sizes;
        std::unique_ptr<std::vector<TypeReferenceFault>> type_reference_faults;
    };
    PerDictionary& entry(const Dictionary* dictionary);

    std::unordered_map<const Dictionary*, PerDictionary> dictionaries_;
};

}  // namespace esi::rules
