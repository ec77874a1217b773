#include "diff/type_names.hpp"

#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/number.hpp"

namespace esi::diff_detail {

namespace {

constexpr int max_depth = 16;  // like resolve_type: deeper nesting is a cycle or hostile input

ResolvedType resolve(const Dictionary* dictionary, std::string_view name) {
    ResolvedType r = resolve_type(dictionary, name);
    if (!r.known) {
        const std::string_view standard = standard_type_name_for(trim(name));
        if (!standard.empty()) r = resolve_type(dictionary, standard);
    }
    return r;
}

bool same_layout(const Dictionary* da, std::string_view ta, const Dictionary* db, std::string_view tb, int depth);

bool same_resolved(const Dictionary* da, const ResolvedType& a, std::string_view ta, const Dictionary* db, const ResolvedType& b,
                   std::string_view tb, int depth) {
    if (a.known != b.known) return false;
    if (!a.known) return normalized_type_name(ta) == normalized_type_name(tb);
    if (a.cycle || b.cycle) return normalized_type_name(ta) == normalized_type_name(tb);
    if (a.bit_size != b.bit_size) return false;
    if (a.is_array != b.is_array || a.is_structure != b.is_structure) return false;
    if ((a.basic == nullptr) != (b.basic == nullptr)) return false;
    if (a.basic && b.basic && a.basic->esi_name != b.basic->esi_name) return false;
    if (a.is_array) {
        if (a.array_elements != b.array_elements || a.array_lower_bound != b.array_lower_bound) return false;
        if (!same_layout(da, a.element_type, db, b.element_type, depth + 1)) return false;
    }
    if (a.is_structure) {
        if (!a.definition || !b.definition) return a.definition == b.definition;
        const auto& xs = a.definition->sub_items;
        const auto& ys = b.definition->sub_items;
        if (xs.size() != ys.size()) return false;
        for (std::size_t i = 0; i < xs.size(); ++i) {
            if (xs[i].subindex != ys[i].subindex || xs[i].bit_size != ys[i].bit_size || xs[i].bit_offset != ys[i].bit_offset)
                return false;
            if (!same_layout(da, xs[i].type, db, ys[i].type, depth + 1)) return false;
        }
    }
    return true;
}

bool same_layout(const Dictionary* da, std::string_view ta, const Dictionary* db, std::string_view tb, int depth) {
    if (depth > max_depth) return normalized_type_name(ta) == normalized_type_name(tb);
    return same_resolved(da, resolve(da, ta), ta, db, resolve(db, tb), tb, depth);
}

}  // namespace

std::string normalized_type_name(std::string_view name) {
    std::string canonical = canonical_type_name(name);
    const TypeName parsed = parse_type_name(canonical);
    if (parsed.kind == TypeName::Kind::named) {
        const std::string_view standard = standard_type_name_for(canonical);
        if (!standard.empty()) return canonical_type_name(standard);
    }
    if (parsed.kind == TypeName::Kind::array) {
        const std::string element = normalized_type_name(parsed.element);
        return "ARRAY [" + std::to_string(parsed.lower_bound) + ".." + std::to_string(parsed.upper_bound) + "] OF " + element;
    }
    return canonical;
}

TypeMatch compare_type_names(std::string_view old_name, std::string_view new_name) {
    if (canonical_type_name(old_name) == canonical_type_name(new_name)) return TypeMatch::same;
    if (normalized_type_name(old_name) == normalized_type_name(new_name)) return TypeMatch::spelling;
    return TypeMatch::different;
}

TypeMatch compare_types(const Dictionary* old_dictionary, std::string_view old_name, const Dictionary* new_dictionary,
                        std::string_view new_name) {
    const bool same_layout_ = same_layout(old_dictionary, old_name, new_dictionary, new_name, 0);
    if (!same_layout_) return TypeMatch::different;
    return canonical_type_name(old_name) == canonical_type_name(new_name) ? TypeMatch::same : TypeMatch::spelling;
}

}  // namespace esi::diff_detail
