#include "check/od_type_references.hpp"

#include "check/last_name_answer.hpp"

namespace esi::rules {

namespace {
// A status with the part of the name at fault as a place in the name, so that it applies to
// every reference spelled alike.
struct NameStatus {
    TypeNameStatus status = TypeNameStatus::resolved;
    std::size_t culprit_at = 0;
    std::size_t culprit_size = 0;
};
}  // namespace

std::vector<TypeReferenceFault> type_reference_faults(const Dictionary& dictionary, const TypeIndex& types) {
    std::vector<TypeReferenceFault> out;
    LastNameAnswer<NameStatus> last_status;
    for_each_type_reference(dictionary, [&](const TypeReference& ref) {
        const NameStatus& status = last_status.get(ref.name, [&](std::string_view name) {
            std::string_view culprit;
            const TypeNameStatus s = types.status(name, &culprit);
            if (s == TypeNameStatus::resolved) return NameStatus{};
            return NameStatus{s, static_cast<std::size_t>(culprit.data() - name.data()), culprit.size()};
        });
        if (status.status != TypeNameStatus::resolved)
            out.push_back(TypeReferenceFault{ref, status.status, ref.name.substr(status.culprit_at, status.culprit_size)});
    });
    return out;
}

}  // namespace esi::rules
