#include "check/od_type_references.hpp"

namespace esi::rules {

std::vector<TypeReferenceFault> type_reference_faults(const Dictionary& dictionary, const TypeIndex& types) {
    std::vector<TypeReferenceFault> out;
    for_each_type_reference(dictionary, [&](const TypeReference& ref) {
        std::string_view culprit;
        const TypeNameStatus status = types.status(ref.name, &culprit);
        if (status != TypeNameStatus::resolved) out.push_back(TypeReferenceFault{ref, status, culprit});
    });
    return out;
}

}  // namespace esi::rules
