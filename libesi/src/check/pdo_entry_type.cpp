#include "check/pdo_entry_type.hpp"

#include <string>

#include "esi/number.hpp"

namespace esi::rules {

namespace {
// A DataType on a BaseType loop has no size or base (od-type-cycle reports the loop).
bool in_cycle(const TypeIndex& types, std::string_view name) {
    const DataType* t = types.find(name);
    return t && t->base_type && types.in_base_type_cycle(*t);
}
}  // namespace

EntryType entry_type(const TypeIndex& types, const PdoEntry& entry) {
    EntryType out;
    if (!entry.data_type) return out;
    const std::string_view text = trim(*entry.data_type);
    if (text.empty()) return out;
    out.present = true;
    std::string_view culprit;
    const TypeNameStatus status = types.status(text, &culprit);
    // "UINT16" is a non-standard spelling unless the Dictionary defines a type of that name.
    if (status == TypeNameStatus::nonstandard) {
        out.nonstandard_name = culprit;
        out.standard_name = standard_type_name_for(culprit);
    }
    // A known spelling (UINT16 for UINT, also inside ARRAY … OF) means its standard type: the other
    // rules judge the entry as that type.
    std::string standard;
    std::string_view resolved = text;
    if (!out.standard_name.empty()) {
        const auto at = text.find(culprit);
        standard = std::string(text.substr(0, at)) + std::string(out.standard_name) + std::string(text.substr(at + culprit.size()));
        resolved = standard;
    }
    out.known = types.status(resolved) == TypeNameStatus::resolved && !in_cycle(types, resolved);
    if (!out.known) return out;
    out.basic = types.basic(resolved);
    out.bit_size = types.bit_size(resolved).value_or(0);
    return out;
}

const EntryType& EntryTypes::of(const PdoEntry& entry) {
    if (!entry.data_type) return absent_;
    return *last_.get(trim(*entry.data_type), [&](std::string_view text) {
        auto it = by_text_.find(text);
        if (it == by_text_.end()) it = by_text_.emplace(text, entry_type(types_, entry)).first;
        return &it->second;  // unordered_map nodes do not move
    });
}

}  // namespace esi::rules
