#include "yaml/type_names.hpp"

#include <vector>

#include "esi/data_types.hpp"
#include "esi/text_distance.hpp"

namespace esi::yaml {

namespace {

// Whether `a` is `b` with two neighbouring letters swapped ("UNIT" for "UINT"): the commonest
// typing slip, which plain edit distance counts as two edits, behind "INT" at one.
bool swapped_neighbours(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    std::size_t i = 0;
    while (i < a.size() && a[i] == b[i]) ++i;
    return i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] && a.substr(i + 2) == b.substr(i + 2);
}

}  // namespace

std::string misspelt_type_message(std::string_view type, const Dictionary& dictionary) {
    const TypeName parsed = parse_type_name(type);
    // In an ARRAY form the element is what may be misspelt.
    std::string_view name = type;
    if (parsed.kind == TypeName::Kind::array) {
        if (parsed.basic) return {};
        name = parsed.element;
    } else if (parsed.kind != TypeName::Kind::named) {
        return {};
    }
    if (name.empty() || dictionary.find_data_type(name)) return {};
    std::string meant(standard_type_name_for(name));
    std::vector<std::string_view> basic_names;
    for (const BasicType& b : basic_types()) {
        basic_names.push_back(b.esi_name);
        if (meant.empty() && swapped_neighbours(name, b.esi_name)) meant = b.esi_name;
    }
    if (meant.empty()) meant = closest_match(name, basic_names);
    if (meant.empty()) return {};
    return "unknown type '" + std::string(name) + "'; did you mean '" + meant +
           "'? (a basic type such as UINT, STRING(n), ARRAY [0..n] OF a type, or a type declared in data_types)";
}

}  // namespace esi::yaml
