#include "check/od_type_index.hpp"

#include <unordered_map>
#include <vector>

#include "esi/data_types.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {
// Real BaseType chains are one or two steps long (an enum on USINT); a bound keeps hostile
// files with long chains linear.
constexpr int max_base_type_steps = 32;

// The basic type a name (not a DataType) stands for: a basic type or STRING(n). Basic names
// are looked up before parsing the name, which costs a TypeName with two strings: the type
// rules ask this of every sub-item, object and PDO entry.
const BasicType* basic_or_string(std::string_view name) {
    if (const BasicType* basic = find_basic_type(name)) return basic;
    const TypeName parsed = parse_type_name(name);
    return parsed.kind == TypeName::Kind::basic || parsed.kind == TypeName::Kind::string ? parsed.basic : nullptr;
}
}  // namespace

TypeIndex::TypeIndex(const Dictionary& dictionary) : TypeIndex(&dictionary) {}

TypeIndex::TypeIndex(const Dictionary* dictionary) : names_(dictionary) {
    if (dictionary) find_cycles(*dictionary);
}

void TypeIndex::find_cycles(const Dictionary& dictionary) {
    // Every DataType has at most one BaseType, so the types form chains that either end or run
    // into one loop. One walk per chain, marking what it passed, finds every loop in linear time.
    enum class State { unvisited, on_path, done };
    // States by position in DataTypes (every DataType pointer here points into it).
    std::vector<State> states(dictionary.data_types.size(), State::unvisited);
    const auto state = [&](const DataType* t) -> State& { return states[static_cast<std::size_t>(t - dictionary.data_types.data())]; };
    const auto next = [&](const DataType* t) -> const DataType* {
        if (!t->base_type) return nullptr;
        const std::string_view base = trim(*t->base_type);
        const DataType* n = find(base);
        // "UINT" defined with BaseType "UINT": a basic type described by itself, not a loop.
        if (n == t && parse_type_name(base).kind != TypeName::Kind::named) return nullptr;
        return n;
    };
    std::vector<const DataType*> path;
    for (const auto& type : dictionary.data_types) {
        const DataType* start = &type;
        // Only the first of a name is indexed; a chain starts at a type with a BaseType (one
        // without is a chain of its own that ends at once, and chains running into it stop there).
        if (!type.base_type || !names_.is_first_of_name(type) || state(start) != State::unvisited) continue;
        path.clear();
        const DataType* t = start;
        while (t && state(t) == State::unvisited) {
            state(t) = State::on_path;
            path.push_back(t);
            t = next(t);
        }
        if (t && state(t) == State::on_path) {
            // The loop is the part of the path from t on.
            bool in_loop = false;
            for (const DataType* p : path) {
                in_loop = in_loop || p == t;
                if (in_loop) in_cycle_.insert(p);
            }
        }
        for (const DataType* p : path) state(p) = State::done;
    }
}

const BasicType* TypeIndex::basic(std::string_view name) const {
    name = trim(name);
    for (int step = 0; step < max_base_type_steps; ++step) {
        const DataType* t = find(name);
        if (!t) return basic_or_string(name);
        if (!t->array_info.empty() || !t->sub_items.empty()) return nullptr;
        const std::string_view base = t->base_type ? trim(*t->base_type) : std::string_view{};
        if (base.empty() || base == name) return basic_or_string(name);  // a DataType named like a basic type ("UINT" with its BitSize) is that type
        name = base;
    }
    return nullptr;  // a BaseType loop, or a chain too long to be real
}

const DataType* TypeIndex::find(std::string_view name) const { return names_.find(trim(name)); }

TypeNameStatus TypeIndex::status(std::string_view name, std::string_view* culprit) const {
    name = trim(name);
    for (int depth = 0; depth < 8; ++depth) {
        if (find_basic_type(name) || find(name)) return TypeNameStatus::resolved;
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
    if (const BasicType* basic = find_basic_type(name)) {  // implied_bit_size's answer, without parsing the name twice
        if (basic->bit_size > 0) return basic->bit_size;
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

TypeIndex::NameFacts TypeIndex::facts(std::string_view name) const {
    name = trim(name);
    NameFacts out;
    // A DataType or a basic type of that name: resolved, with that type's size (what status()
    // and bit_size() find first).
    const auto size = [](std::uint64_t bits) { return bits > 0 ? std::optional<std::uint64_t>(bits) : std::nullopt; };
    if (const DataType* t = find(name)) {
        out.bit_size = size(t->bit_size);
        return out;
    }
    if (const BasicType* basic = find_basic_type(name)) {
        out.bit_size = size(basic->bit_size);
        return out;
    }
    out.status = status(name, &out.culprit);  // STRING(n), arrays and names that do not resolve
    out.bit_size = bit_size(name);
    return out;
}

bool TypeIndex::in_base_type_cycle(const DataType& type) const { return in_cycle_.count(&type) != 0; }

bool TypeIndex::is_first_of_name(const DataType& type) const {
    // find() trims the name it is given, so a name with blanks around it never finds its own DataType.
    return names_.is_first_of_name(type) && trim(type.name).size() == type.name.size();
}

}  // namespace esi::rules
