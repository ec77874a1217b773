#include "doc/layout_marks.hpp"

#include <map>
#include <string>

namespace esi::doc {

namespace {

// "0x6000:01#2": the address and which mapping of it this is; padding has none.
std::vector<std::string> pairing_keys(const std::vector<LayoutField>& fields) {
    std::vector<std::string> keys;
    keys.reserve(fields.size());
    std::map<std::string, int> seen;
    for (const LayoutField& f : fields) {
        if (f.padding || f.address.empty()) {
            keys.emplace_back();
            continue;
        }
        keys.push_back(f.address + "#" + std::to_string(seen[f.address]++));
    }
    return keys;
}

FieldMark mark_of(const LayoutField& mine, const LayoutField& theirs) {
    if (mine.bit_size != theirs.bit_size) return FieldMark::resized;
    if (mine.bit_offset != theirs.bit_offset) return FieldMark::moved;
    return FieldMark::none;
}

}  // namespace

void mark_changes(std::vector<LayoutField>& old_fields, std::vector<LayoutField>& new_fields) {
    const std::vector<std::string> old_keys = pairing_keys(old_fields);
    const std::vector<std::string> new_keys = pairing_keys(new_fields);
    std::map<std::string, std::size_t> old_by_key, new_by_key;
    for (std::size_t i = 0; i < old_keys.size(); ++i)
        if (!old_keys[i].empty()) old_by_key.emplace(old_keys[i], i);
    for (std::size_t i = 0; i < new_keys.size(); ++i)
        if (!new_keys[i].empty()) new_by_key.emplace(new_keys[i], i);
    for (std::size_t i = 0; i < old_fields.size(); ++i) {
        if (old_keys[i].empty()) continue;
        const auto it = new_by_key.find(old_keys[i]);
        old_fields[i].mark = it == new_by_key.end() ? FieldMark::removed : mark_of(old_fields[i], new_fields[it->second]);
    }
    for (std::size_t i = 0; i < new_fields.size(); ++i) {
        if (new_keys[i].empty()) continue;
        const auto it = old_by_key.find(new_keys[i]);
        new_fields[i].mark = it == old_by_key.end() ? FieldMark::added : mark_of(new_fields[i], old_fields[it->second]);
    }
}

bool same_layout(const std::vector<LayoutField>& a, const std::vector<LayoutField>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const LayoutField& x = a[i];
        const LayoutField& y = b[i];
        if (x.address != y.address || x.bit_offset != y.bit_offset || x.bit_size != y.bit_size || x.padding != y.padding ||
            x.type != y.type || x.name != y.name)
            return false;
    }
    return true;
}

}  // namespace esi::doc
