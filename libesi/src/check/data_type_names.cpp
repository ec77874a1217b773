#include "check/data_type_names.hpp"

#include <bit>
#include <cstdint>

namespace esi::rules {

DataTypeNames::DataTypeNames(const Dictionary* dictionary) : dictionary_(dictionary) {
    if (!dictionary || dictionary->data_types.empty()) return;
    const auto& types = dictionary->data_types;
    slots_.resize(std::bit_ceil(2 * types.size()));
    first_of_name_.resize(types.size());
    for (std::size_t t = 0; t < types.size(); ++t) {
        std::size_t i = home(types[t].name);
        while (slots_[i].type && slots_[i].name != types[t].name) i = (i + 1) & (slots_.size() - 1);
        if (slots_[i].type) continue;  // the first of a name stays
        slots_[i] = Slot{types[t].name, &types[t]};
        first_of_name_[t] = true;
    }
}

bool DataTypeNames::is_first_of_name(const DataType& type) const {
    return dictionary_ && first_of_name_[static_cast<std::size_t>(&type - dictionary_->data_types.data())];
}

std::size_t DataTypeNames::home(std::string_view name) const {
    // FNV-1a (64-bit): a few instructions per character, and type names are short.
    std::uint64_t hash = 14695981039346656037ull;
    for (const unsigned char c : name) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return static_cast<std::size_t>(hash) & (slots_.size() - 1);
}

const DataType* DataTypeNames::find(std::string_view name) const {
    if (slots_.empty()) return nullptr;
    for (std::size_t i = home(name); slots_[i].type; i = (i + 1) & (slots_.size() - 1))
        if (slots_[i].name == name) return slots_[i].type;
    return nullptr;
}

}  // namespace esi::rules
