#include "esi/model/object_layout.hpp"

#include <algorithm>
#include <charconv>

namespace esi {

namespace {
constexpr int max_type_depth = 16;
}

std::string_view to_string(ObjectCode code) {
    switch (code) {
        case ObjectCode::var: return "VAR";
        case ObjectCode::array: return "ARRAY";
        case ObjectCode::record: return "RECORD";
    }
    return "VAR";
}

namespace {

// How a type name is looked up: by scanning the Dictionary's DataTypes (one-off questions) or
// through a DataTypeIndex built once (the many questions of a lint run).
struct ScannedTypes {
    const Dictionary* dictionary;
    [[nodiscard]] const DataType* find(std::string_view name) const { return dictionary ? dictionary->find_data_type(name) : nullptr; }
};
struct IndexedTypes {
    const DataTypeIndex& index;
    [[nodiscard]] const DataType* find(std::string_view name) const { return index.find(name); }
};

// Whether parse_type_name reads more than a plain name into `name`, which is not spelled as a
// basic type: only STRING(n), ARRAY [..] OF and a basic type's name among blanks are more. Record
// and enum DataTypes (DT1018) are none of these, and skip the parse and its copies of the name.
bool parse_may_tell_more(std::string_view name) {
    const std::string_view s = trim(name);
    return s.size() != name.size() || s.starts_with("STRING") || s.starts_with("ARRAY");
}

template <class Types>
ResolvedType resolve(const Types& types, std::string_view type_name) {
    ResolvedType out;
    // Views into the caller's name and the Dictionary's BaseType strings, which outlive the walk.
    std::string_view current = trim(type_name);
    for (int depth = 0; depth < max_type_depth; ++depth) {
        const DataType* definition = types.find(current);
        if (definition) {
            out.known = true;
            if (!out.definition) {
                out.definition = definition;
                out.bit_size = definition->bit_size;
                out.is_structure = !definition->sub_items.empty();
                if (!definition->array_info.empty()) {
                    out.is_array = true;
                    out.array_lower_bound = definition->array_info.front().lower_bound;
                    out.array_elements = definition->array_info.front().elements > 0
                                             ? static_cast<std::uint64_t>(definition->array_info.front().elements)
                                             : 0;
                    out.element_type = definition->base_type.value_or("");
                }
            }
            if (definition->base_type && !definition->base_type->empty() && *definition->base_type != current) {
                if (out.is_array && depth == 0) {
                    // The base type of an array definition is its element type; the array itself ends here.
                    out.basic = nullptr;
                    const ResolvedType element = resolve(types, *definition->base_type);
                    if (element.cycle) out.cycle = true;
                    return out;
                }
                current = *definition->base_type;
                continue;
            }
            // A DataType named like a basic type (Beckhoff lists "UINT" with its BitSize).
            if (const BasicType* basic = find_basic_type(current)) {  // parse_type_name's answer, without its copies
                out.basic = basic;
                return out;
            }
            if (!parse_may_tell_more(current)) return out;
            const TypeName parsed = parse_type_name(current);
            if (parsed.kind == TypeName::Kind::basic) out.basic = parsed.basic;
            else if (parsed.kind == TypeName::Kind::string) out.basic = parsed.basic;
            else if (parsed.kind == TypeName::Kind::array && !out.is_array) {
                out.is_array = true;
                out.array_lower_bound = parsed.lower_bound;
                out.array_elements = parsed.element_count();
                out.element_type = parsed.element;
            }
            return out;
        }
        if (const BasicType* basic = find_basic_type(current)) {  // parse_type_name's answer, without its copies
            out.known = true;
            out.basic = basic;
            if (!out.definition) out.bit_size = basic->bit_size;
            return out;
        }
        const TypeName parsed = parse_type_name(current);
        switch (parsed.kind) {
            case TypeName::Kind::basic:
            case TypeName::Kind::string:
                out.known = true;
                out.basic = parsed.basic;
                if (!out.definition) out.bit_size = implied_bit_size(current).value_or(0);
                return out;
            case TypeName::Kind::array:
                out.known = true;
                if (!out.definition) {
                    out.is_array = true;
                    out.array_lower_bound = parsed.lower_bound;
                    out.array_elements = parsed.element_count();
                    out.element_type = parsed.element;
                    out.bit_size = implied_bit_size(current).value_or(0);
                }
                return out;
            case TypeName::Kind::named: return out;
        }
    }
    out.cycle = true;
    return out;
}

}  // namespace

DataTypeIndex::DataTypeIndex(const Dictionary* dictionary) : dictionary_(dictionary), basic_named_(basic_types().size(), nullptr) {
    if (!dictionary) return;
    by_name_.reserve(dictionary->data_types.size());
    for (const auto& t : dictionary->data_types) {
        // The first of a name wins, in both tables.
        if (const BasicType* basic = find_basic_type(t.name)) {
            const DataType*& slot = basic_named_[static_cast<std::size_t>(basic - basic_types().data())];
            if (!slot) slot = &t;
        } else {
            by_name_.emplace(std::string_view(t.name), &t);
        }
    }
}

const DataType* DataTypeIndex::find(std::string_view name) const {
    if (const BasicType* basic = find_basic_type(name)) return basic_named_[static_cast<std::size_t>(basic - basic_types().data())];
    const auto it = by_name_.find(name);
    return it == by_name_.end() ? nullptr : it->second;
}

ResolvedType resolve_type(const Dictionary* dictionary, std::string_view type_name) { return resolve(ScannedTypes{dictionary}, type_name); }
ResolvedType resolve_type(const DataTypeIndex& types, std::string_view type_name) { return resolve(IndexedTypes{types}, type_name); }

const ObjectEntry* ObjectLayout::entry(std::uint32_t subindex) const {
    for (const auto& e : entries)
        if (e.subindex == subindex) return &e;
    return nullptr;
}

namespace {

// "SubIndex 001" (three digits at least), the name of an array element. Formatted in a buffer on
// the stack and copied into the string once (the name fits its inline storage): dictionaries have
// thousands of array elements.
std::string subindex_name(std::uint32_t subindex) {
    constexpr std::size_t prefix = 9;  // "SubIndex "
    char text[prefix + 10] = "SubIndex 000";  // zero padding for numbers of fewer than three digits
    char digits[10];
    const auto count = static_cast<std::size_t>(std::to_chars(digits, digits + sizeof digits, subindex).ptr - digits);
    const std::size_t width = std::max<std::size_t>(count, 3);
    std::copy(digits, digits + count, text + prefix + width - count);
    return std::string(text, prefix + width);
}

// Adds the elements of an array-typed item starting at `offset`.
template <class Types>
void add_array_elements(const Types& types, const ResolvedType& array, const DataTypeSubItem* item, std::uint64_t offset,
                        const ObjectFlags* flags, ObjectLayout& layout) {
    const ResolvedType element = resolve(types, array.element_type);
    std::uint64_t element_bits = element.bit_size;
    if (element_bits == 0 && array.array_elements > 0) element_bits = array.bit_size / array.array_elements;
    // Guard against absurd element counts in hostile files: a CoE object has at most 255 sub-indices.
    const std::uint64_t count = std::min<std::uint64_t>(array.array_elements, 255);
    const std::int64_t first = array.array_lower_bound > 0 ? array.array_lower_bound : 1;
    layout.entries.reserve(layout.entries.size() + count);
    for (std::uint64_t i = 0; i < count; ++i) {
        const std::int64_t sub = first + static_cast<std::int64_t>(i);
        if (sub > 255) break;
        ObjectEntry& e = layout.entries.emplace_back();
        e.subindex = static_cast<std::uint32_t>(sub);
        e.name = subindex_name(e.subindex);
        e.type = array.element_type;
        e.basic = element.basic;
        e.bit_size = element_bits;
        e.bit_offset = offset + i * element_bits;
        e.flags = flags;
        e.type_item = item;
    }
}

template <class Types>
ObjectLayout build_layout(const Types& types, const Object& object) {
    ObjectLayout layout;
    const ObjectFlags* object_flags = object.flags ? &*object.flags : nullptr;
    const ResolvedType type = resolve(types, object.type);

    if (type.is_structure && type.definition) {
        bool has_array_item = false;
        std::uint32_t next_subindex = 0;
        layout.entries.reserve(type.definition->sub_items.size());  // array items reserve their elements
        // Runs of SubItems share a type (the UDINT entries of a PDO mapping, the BOOLs of a status
        // record): the type is resolved once per run, not once per SubItem.
        ResolvedType item_type;
        const std::string* item_type_name = nullptr;
        for (const auto& item : type.definition->sub_items) {
            if (!item_type_name || item.type != *item_type_name) item_type = resolve(types, item.type);
            item_type_name = &item.type;
            const ObjectFlags* flags = item.flags ? &*item.flags : object_flags;
            if (item_type.is_array && !item.subindex) {
                has_array_item = true;
                const std::size_t before = layout.entries.size();
                add_array_elements(types, item_type, &item, item.bit_offset, flags, layout);
                if (layout.entries.size() > before) next_subindex = layout.entries.back().subindex + 1;
                continue;
            }
            ObjectEntry& e = layout.entries.emplace_back();
            e.subindex = item.subindex.value_or(next_subindex);
            next_subindex = e.subindex + 1;
            e.name = item.name;
            e.type = item.type;
            e.basic = item_type.basic;
            e.bit_size = item.bit_size;
            e.bit_offset = item.bit_offset;
            e.flags = flags;
            e.type_item = &item;
        }
        layout.code = has_array_item ? ObjectCode::array : ObjectCode::record;
    } else if (type.is_array) {
        // An object typed directly as an array: sub-index 0 holds the element count.
        layout.code = ObjectCode::array;
        ObjectEntry count;
        count.subindex = 0;
        count.name = subindex_name(0);
        count.type = "USINT";
        static const BasicType* const usint = find_basic_type("USINT");
        count.basic = usint;
        count.bit_size = 8;
        count.flags = object_flags;
        layout.entries.push_back(std::move(count));
        add_array_elements(types, type, nullptr, 16, object_flags, layout);
    } else {
        ObjectEntry e;
        e.subindex = 0;
        e.name = primary_text(object.names);
        e.type = object.type;
        e.basic = type.basic;
        e.bit_size = object.bit_size;
        e.flags = object_flags;
        e.info = object.info ? &*object.info : nullptr;
        layout.entries.push_back(std::move(e));
        return layout;
    }

    // Object/Info/SubItem lists the values of the sub-entries in order; names confirm the match.
    if (object.info) {
        const auto& values = object.info->sub_items;
        for (std::size_t k = 0; k < layout.entries.size(); ++k) {
            const ObjectSubItemInfo* match = nullptr;
            if (k < values.size() && (values[k].name == layout.entries[k].name || values[k].name.empty() ||
                                      layout.entries[k].type_item == nullptr || values.size() == layout.entries.size()))
                match = &values[k];
            if (!match) {
                for (const auto& v : values)
                    if (v.name == layout.entries[k].name) match = &v;
            }
            if (match) {
                layout.entries[k].info = &match->info;
                if (!match->name.empty() && layout.entries[k].type_item && layout.entries[k].type_item->subindex == std::nullopt)
                    layout.entries[k].name = match->name;  // array elements take the object's names
            }
        }
    }
    return layout;
}

}  // namespace

ObjectLayout layout_of(const Dictionary* dictionary, const Object& object) { return build_layout(ScannedTypes{dictionary}, object); }
ObjectLayout layout_of(const DataTypeIndex& types, const Object& object) { return build_layout(IndexedTypes{types}, object); }

}  // namespace esi
