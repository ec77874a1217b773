#pragma once
// What several rules compute about the same Dictionary, computed once per lint run: its
// DataTypes by name (with BaseType loops), its objects by index and their layouts, its type
// references with what their names mean; and for each device and module what its PDO entries'
// DataTypes mean and which objects they map. Rules take these from the cache
// (RuleContext::cache) and never build their own, so each index and each object layout is built
// at most once per Dictionary and run, however many rules ask.
//
// A cache belongs to one run of the rules over one document (run_rules) on one thread; the
// model must not change while it lives. It also lists the document's devices, Dictionaries and
// PDO owners for the rules, once.

#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "check/od_scope.hpp"
#include "check/od_type_index.hpp"
#include "check/od_type_references.hpp"
#include "check/od_type_sizes.hpp"
#include "check/pdo_entry_facts.hpp"
#include "check/pdo_entry_type.hpp"
#include "check/pdo_scope.hpp"
#include "check/queries.hpp"

namespace esi::rules {

class RuleCache {
public:
    // The document's devices, its Dictionaries with their owners and its PDO owners, listed once
    // per run: nearly every rule starts from one of these lists.
    [[nodiscard]] const std::vector<const Device*>& devices(const EsiDocument& document);
    [[nodiscard]] const std::vector<DictionaryScope>& dictionary_scopes(const EsiDocument& document);
    [[nodiscard]] const std::vector<PdoScope>& pdo_scopes(const EsiDocument& document);

    // A null Dictionary gives the index of an owner without one: only basic types resolve.
    [[nodiscard]] const TypeIndex& types(const Dictionary* dictionary);
    [[nodiscard]] const DictionaryIndex& objects(const Dictionary* dictionary);
    // The PDO entries of a device or module, with what their DataTypes mean and what they map.
    [[nodiscard]] PdoEntryFacts& pdo_entries(const PdoScope& scope);
    // The DataTypes' sizes as their users see them (a Dictionary, not null).
    [[nodiscard]] const DataTypeSizes& type_sizes(const Dictionary& dictionary);
    // Every type reference with what its name means (a Dictionary, not null).
    [[nodiscard]] const std::vector<ReferencedType>& referenced_types(const Dictionary& dictionary);

private:
    // Each part built when first asked for, in place: map nodes do not move, so the references
    // handed out stay valid.
    struct PerDictionary {
        std::optional<TypeIndex> types;
        std::optional<DictionaryIndex> objects;
        std::optional<EntryTypes> entry_types;
        std::optional<DataTypeSizes> type_sizes;
        std::optional<std::vector<ReferencedType>> referenced_types;
    };
    PerDictionary& entry(const Dictionary* dictionary);

    // The document's lists, made when first asked for.
    struct DocumentLists {
        std::optional<std::vector<const Device*>> devices;
        std::optional<std::vector<DictionaryScope>> dictionary_scopes;
        std::optional<std::vector<PdoScope>> pdo_scopes;
    };
    DocumentLists& lists(const EsiDocument& document);

    const EsiDocument* listed_document_ = nullptr;
    DocumentLists lists_;
    std::unordered_map<const Dictionary*, PerDictionary> dictionaries_;
    // By the owner's RxPdo list, which identifies the device or module.
    std::unordered_map<const std::vector<Pdo>*, std::unique_ptr<PdoEntryFacts>> pdo_entries_;
};

}  // namespace esi::rules
