// The index's lookups and build_index, which picks the front end by content.

#include "navigate/index.hpp"

#include <algorithm>

#include "esi/number.hpp"

namespace esi::navigate {

std::uint64_t PdoDef::bit_size() const {
    std::uint64_t bits = 0;
    for (const auto& entry : entries) bits += entry.bit_len;
    return bits;
}

const ObjectDef* Scope::find_object(std::uint32_t index) const {
    for (const auto& object : objects)
        if (object.index == index) return &object;
    return nullptr;
}

const DataTypeDef* Scope::find_data_type(std::string_view name) const {
    for (const auto& type : data_types)
        if (type.name == name) return &type;
    return nullptr;
}

const PdoDef* Scope::find_pdo(std::uint32_t index) const {
    for (const auto& pdo : pdos)
        if (pdo.index == index) return &pdo;
    return nullptr;
}

const SmDef* Scope::find_sm(std::uint32_t number) const {
    return number < sms.size() ? &sms[number] : nullptr;
}

const Occurrence* Index::occurrence_at(std::size_t offset) const {
    // The last occurrence starting at or before the offset; tokens never overlap.
    auto after = std::upper_bound(occurrences.begin(), occurrences.end(), offset,
                                  [](std::size_t value, const Occurrence& o) { return value < o.span.begin; });
    if (after == occurrences.begin()) return nullptr;
    const Occurrence& candidate = *(after - 1);
    return offset <= candidate.span.end ? &candidate : nullptr;
}

std::optional<std::uint32_t> Index::scope_at(std::size_t offset) const {
    std::optional<std::uint32_t> found;
    for (std::uint32_t i = 0; i < scopes.size(); ++i) {
        const Span& element = scopes[i].element;
        if (element.begin <= offset && offset <= element.end) found = i;
    }
    return found;
}

std::optional<Span> Index::definition_of(const Occurrence& occurrence) const {
    const auto target = find_definition(occurrence);
    // What derivation adds to a YAML source has no text to go to.
    if (!target || target->empty()) return std::nullopt;
    return target;
}

std::optional<Span> Index::find_definition(const Occurrence& occurrence) const {
    if (occurrence.scope >= scopes.size()) return std::nullopt;
    const Scope& scope = scopes[occurrence.scope];
    switch (occurrence.target) {
        case Target::object: {
            const ObjectDef* object = scope.find_object(occurrence.key);
            if (!object) return std::nullopt;
            // An entry mapping a sub-item points at the sub-item: where the document writes it
            // for this object, else in the object's type.
            if (occurrence.sub && *occurrence.sub != 0) {
                for (const auto& [subindex, span] : object->sub_decls)
                    if (subindex == *occurrence.sub) return span;
                if (const DataTypeDef* type = scope.find_data_type(object->type))
                    for (const auto& item : type->sub_items)
                        if (item.subindex == occurrence.sub && !item.decl.empty()) return item.decl;
            }
            return object->decl;
        }
        case Target::data_type: {
            const DataTypeDef* type = scope.find_data_type(token(occurrence.span));
            if (!type) return std::nullopt;
            return type->decl;
        }
        case Target::pdo: {
            const PdoDef* pdo = scope.find_pdo(occurrence.key);
            if (!pdo) return std::nullopt;
            return pdo->decl;
        }
        case Target::sync_manager: {
            const SmDef* sm = scope.find_sm(occurrence.key);
            if (!sm) return std::nullopt;
            return sm->decl;
        }
    }
    return std::nullopt;
}

bool Index::same_target(const Occurrence& a, const Occurrence& b) const {
    if (a.scope != b.scope || a.target != b.target) return false;
    if (a.target == Target::data_type) return token(a.span) == token(b.span);
    return a.key == b.key;
}

void Index::finish() {
    std::stable_sort(occurrences.begin(), occurrences.end(),
                     [](const Occurrence& a, const Occurrence& b) { return a.span.begin < b.span.begin; });
    lines = LineMap(text);
}

std::optional<std::uint32_t> parse_index_number(std::string_view text) {
    const ParsedNumber parsed = parse_number(text);
    if (!parsed.ok() || parsed.value.negative || parsed.value.magnitude > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<std::uint32_t>(parsed.value.magnitude);
}

void IndexDeleter::operator()(Index* index) const { delete index; }

IndexPtr build_index(std::string_view text, const std::string& path) {
    IndexPtr index(new Index());
    index->path = path;
    index->text.assign(text);
    // By content, as esi::load_document decides: an XML document starts with '<' after a
    // byte-order mark and blanks; a YAML source never does.
    std::string_view rest = text;
    if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);
    rest = trim(rest);
    index->yaml = !rest.empty() && rest.front() != '<';
    if (index->yaml)
        index_yaml(*index);
    else
        index_xml(*index);
    index->finish();
    return index;
}

}  // namespace esi::navigate
