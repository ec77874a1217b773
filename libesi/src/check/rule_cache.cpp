#include "check/rule_cache.hpp"

namespace esi::rules {

RuleCache::DocumentLists& RuleCache::lists(const EsiDocument& document) {
    if (listed_document_ != &document) {  // one document per cache; another starts afresh
        listed_document_ = &document;
        lists_ = DocumentLists{};
    }
    return lists_;
}

const std::vector<const Device*>& RuleCache::devices(const EsiDocument& document) {
    DocumentLists& l = lists(document);
    if (!l.devices) l.devices = all_devices(document);
    return *l.devices;
}

const std::vector<DictionaryScope>& RuleCache::dictionary_scopes(const EsiDocument& document) {
    DocumentLists& l = lists(document);
    if (!l.dictionary_scopes) l.dictionary_scopes = rules::dictionary_scopes(document);
    return *l.dictionary_scopes;
}

const std::vector<PdoScope>& RuleCache::pdo_scopes(const EsiDocument& document) {
    DocumentLists& l = lists(document);
    if (!l.pdo_scopes) l.pdo_scopes = rules::pdo_scopes(document);
    return *l.pdo_scopes;
}

RuleCache::PerDictionary& RuleCache::entry(const Dictionary* dictionary) {
    PerDictionary& e = dictionaries_[dictionary];
    if (!e.types) e.types.emplace(dictionary);
    return e;
}

const TypeIndex& RuleCache::types(const Dictionary* dictionary) { return *entry(dictionary).types; }

const DictionaryIndex& RuleCache::objects(const Dictionary* dictionary) {
    PerDictionary& e = entry(dictionary);
    if (!e.objects) e.objects.emplace(dictionary);
    return *e.objects;
}

PdoEntryFacts& RuleCache::pdo_entries(const PdoScope& scope) {
    std::unique_ptr<PdoEntryFacts>& facts = pdo_entries_[scope.rx_pdos];
    if (!facts) {
        const DictionaryIndex& index = objects(scope.dictionary);
        PerDictionary& e = entry(scope.dictionary);
        if (!e.entry_types) e.entry_types.emplace(*e.types);
        facts = std::make_unique<PdoEntryFacts>(scope, *e.entry_types, index);
    }
    return *facts;
}

const DataTypeSizes& RuleCache::type_sizes(const Dictionary& dictionary) {
    PerDictionary& e = entry(&dictionary);
    if (!e.type_sizes) e.type_sizes.emplace(dictionary, *e.types);
    return *e.type_sizes;
}

const std::vector<ReferencedType>& RuleCache::referenced_types(const Dictionary& dictionary) {
    PerDictionary& e = entry(&dictionary);
    if (!e.referenced_types) e.referenced_types = rules::referenced_types(dictionary, *e.types);
    return *e.referenced_types;
}

}  // namespace esi::rules
