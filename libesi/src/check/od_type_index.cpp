#include "check/od_type_index.hpp"

#include "esi/data_types.hpp"
#include "esi/number.hpp"

namespace esi::rules {

TypeIndex::TypeIndex(const Dictionary& dictionary) {
    types_.reserve(dictionary.data_types.size());
    for (const auto& t : dictionary.data_types) types_.emplace(std::string_view(t.name), &t);
}

TypeIndex::TypeIndex(const Dictionary* dictionary) {
    if (!dictionary) return;
    types_.reserve(dictionary->data_types.size());
    for (const auto& t : dictionary->data_types) types_.emplace(std::string_view(t.name), &t);
}

const BasicType* TypeIndex::basic(std::string_view name) const {
    name = trim(name);
    for (std::size_t step = 0; step <= types_.size(); ++step) {
        const DataType* t = find(name);
        if (!t) {
            const TypeName parsed = parse_type_name(name);
            return parsed.kind == TypeName::Kind::basic || parsed.kind == TypeName::Kind::string ? parsed.basic : nullptr;
        }
        if (!t->array_info.empty() || !t->sub_items.empty()) return nullptr;
        const std::string_view base = t->base_type ? trim(*t->base_type) : std::string_view{};
        if (base.empty() || base == name) {
            // A DataType named like a basic type ("UINT" with its BitSize) is that type.
            const TypeName parsed = parse_type_name(name);
            return parsed.kind == TypeName::Kind::basic || parsed.kind == TypeName::Kind::string ? parsed.basic : nullptr;
        }
        name = base;
    }
    return nullptr;  // a BaseType cycle
}

const DataType* TypeIndex::find(std::string_view name) const {
    const auto it = types_.find(trim(name));
    return it == types_.end() ? nullptr : it->second;
}

TypeNameStatus TypeIndex::status(std::string_view name, std::string_view* culprit) const {
    name = trim(name);
    for (int depth = 0; depth < 8; ++depth) {
        if (find(name)) return TypeNameStatus::resolved;
        const TypeName parsed = parse_type_name(name);
        if (parsed.kind == TypeName::Kind::basic || parsed.kind == TypeName::Kind::string) return TypeNameStatus::resolved;
        if (parsed.kind == TypeName::Kind::array) {
            // Continue with the element type; parsed.element owns its text, so find it in `name`.
            const auto at = name.rfind(parsed.element);
            if (at == std::string_view::npos) return TypeNameStatus::resolved;
            name = name.substr(at, parsed.element.size());
            continue;
        }
        if (culprit) *culprit = name;
        return standard_type_name_for(name).empty() ? TypeNameStatus::unresolved : TypeNameStatus::nonstandard;
    }
    return TypeNameStatus::resolved;  // absurdly nested arrays: nothing useful to say
}

std::optional<std::uint64_t> TypeIndex::bit_size(std::string_view name) const {
    name = trim(name);
    if (const DataType* t = find(name)) {
        if (t->bit_size > 0) return t->bit_size;
        return std::nullopt;
    }
    const TypeName parsed = parse_type_name(name);
    if (parsed.kind == TypeName::Kind::array) {
        const auto at = name.rfind(parsed.element);
        if (at == std::string_view::npos || parsed.element_count() == 0) return std::nullopt;
        const std::string_view element = name.substr(at, parsed.element.size());
        if (element == name) return std::nullopt;
        const std::optional<std::uint64_t> element_bits = bit_size(element);
        if (!element_bits) return std::nullopt;
        return *element_bits * parsed.element_count();
    }
    return implied_bit_size(name);
}

bool TypeIndex::in_base_type_cycle(const DataType& type) const {
    const DataType* current = &type;
    // A chain that does not return within as many steps as there are types does not return.
    for (std::size_t step = 0; step <= types_.size(); ++step) {
        if (!current->base_type) return false;
        const std::string_view base = trim(*current->base_type);
        const DataType* next = find(base);
        if (!next) return false;
        // "UINT" defined with BaseType "UINT": a basic type described by itself, not a loop.
        if (next == current && parse_type_name(base).kind != TypeName::Kind::named) return false;
        if (next == &type) return true;
        current = next;
    }
    return false;
}

}  // namespace esi::rules
