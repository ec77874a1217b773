#include "esi/diff/filter.hpp"

#include <algorithm>

namespace esi {

void keep_classes(DiffResult& result, const std::set<ChangeClass>& classes) {
    std::erase_if(result.changes, [&](const Change& c) { return !classes.contains(c.change_class); });
    result.verdict = Verdict::identical;
    for (const auto& c : result.changes) result.verdict = std::max(result.verdict, verdict_of(c.change_class));
}

std::optional<ChangeClass> change_class_named(std::string_view name) {
    for (const ChangeClass c : {ChangeClass::cosmetic, ChangeClass::compatible, ChangeClass::breaking})
        if (to_string(c) == name) return c;
    return std::nullopt;
}

}  // namespace esi
