#include "check/od_type_references.hpp"

#include "check/last_name_answer.hpp"

namespace esi::rules {

namespace {
// What a name means, with the part of the name at fault as a place in the name, so that it
// applies to every reference spelled alike.
struct NameMeaning {
    TypeNameStatus status = TypeNameStatus::resolved;
    std::size_t culprit_at = 0;
    std::size_t culprit_size = 0;
    std::optional<std::uint64_t> bit_size;
};
}  // namespace

std::vector<ReferencedType> referenced_types(const Dictionary& dictionary, const TypeIndex& types) {
    std::vector<ReferencedType> out;
    std::size_t count = dictionary.objects.size();
    for (const auto& type : dictionary.data_types) count += 1 + type.sub_items.size();
    out.reserve(count);  // at most one reference per Object, DataType and SubItem
    LastNameAnswer<NameMeaning> last_meaning;
    for_each_type_reference(dictionary, [&](const TypeReference& ref) {
        const NameMeaning& meaning = last_meaning.get(ref.name, [&](std::string_view name) {
            const TypeIndex::NameFacts facts = types.facts(name);
            if (facts.status == TypeNameStatus::resolved) return NameMeaning{.bit_size = facts.bit_size};
            return NameMeaning{facts.status, static_cast<std::size_t>(facts.culprit.data() - name.data()), facts.culprit.size(),
                               facts.bit_size};
        });
        out.push_back(ReferencedType{ref, meaning.status, ref.name.substr(meaning.culprit_at, meaning.culprit_size), meaning.bit_size});
    });
    return out;
}

}  // namespace esi::rules
