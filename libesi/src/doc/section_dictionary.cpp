// The object dictionary of a page: every object sorted by index, a VAR as one row, an ARRAY or
// RECORD as its object row followed by a row per sub-index, with type, access, PDO mapping,
// default, minimum, maximum and unit as the file gives them (values decoded the way the entry's
// type reads them, esi/codegen/entry_values.hpp).

#include <algorithm>
#include <cstdio>
#include <string>

#include "doc/markup.hpp"
#include "doc/sections.hpp"
#include "esi/codegen/entry_values.hpp"
#include "esi/encoding.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/plural.hpp"

namespace esi::doc {

namespace {

using codegen::DecodedValue;

constexpr std::size_t shown_bytes = 32;  // longer octet strings are cut, with "…"

std::string bytes_text(std::string_view bytes) {
    std::string out;
    char buffer[4];
    for (std::size_t k = 0; k < bytes.size() && k < shown_bytes; ++k) {
        std::snprintf(buffer, sizeof buffer, "%02X", static_cast<unsigned char>(bytes[k]));
        if (!out.empty()) out += ' ';
        out += buffer;
    }
    if (bytes.size() > shown_bytes) out += " …";
    return out;
}

std::string value_text(const DecodedValue& v, const ObjectEntry& entry) {
    switch (v.kind) {
        case DecodedValue::Kind::none: return {};
        case DecodedValue::Kind::signed_integer: return std::to_string(v.i);
        case DecodedValue::Kind::unsigned_integer:
            // Bit strings are patterns, not quantities: hex in the width of the type.
            if (entry.basic && entry.basic->type_class == TypeClass::bit_string)
                return hex(v.bits, static_cast<int>(std::max<std::uint64_t>(2, (entry.bit_size + 3) / 4)));
            return std::to_string(v.bits);
        case DecodedValue::Kind::real: {
            char buffer[40];
            std::snprintf(buffer, sizeof buffer, "%.9g", v.r);
            return buffer;
        }
        case DecodedValue::Kind::string: {
            if (!is_valid_utf8(v.text)) return bytes_text(v.text);
            std::string out = v.text;
            // A STRING(n) default is padded with NULs; control characters do not belong in a cell.
            while (!out.empty() && out.back() == '\0') out.pop_back();
            for (char& c : out)
                if (static_cast<unsigned char>(c) < 0x20) c = ' ';
            return "\"" + out + "\"";
        }
        case DecodedValue::Kind::bytes: return bytes_text(v.text);
    }
    return {};
}

std::string number_text(const Number& n) { return (n.negative ? "-" : "") + std::to_string(n.magnitude); }

ViewValue entry_view(const ObjectEntry& e, std::string_view name, const DataTypeIndex& types, const PageContext& context) {
    PageObject o(*context.arena);
    const codegen::EntryValues values = codegen::decode_entry_values(e);
    // An enumeration (DataType with EnumInfo) reads by its texts: the default with its name, and
    // every value it can take.
    const DataType* enumeration = types.find(e.type);
    if (enumeration && enumeration->enums.empty()) enumeration = nullptr;
    std::string default_text = value_text(values.default_value, e);
    std::string enum_values;
    if (enumeration) {
        for (const EnumValue& v : enumeration->enums) {
            const std::string value = number_text(v.value);
            const std::string& text = context.text(v.texts);
            if (!enum_values.empty()) enum_values += ", ";
            enum_values += value + " = " + text;
            if (!default_text.empty() && value == default_text && !text.empty()) default_text += " (" + text + ")";
        }
    }
    o.add("subindex_hex", hex(e.subindex, 2));
    o.add("name", name);
    o.add("type", e.type);
    o.add("bit_size", e.bit_size);
    o.add("access", e.flags && e.flags->access ? *e.flags->access : std::string());
    o.add("pdo_mapping", e.flags && e.flags->pdo_mapping ? *e.flags->pdo_mapping : std::string());
    o.add("default", default_text);
    o.add("enum_values", enum_values);
    o.add("min", value_text(values.min, e));
    o.add("max", value_text(values.max, e));
    o.add("unit", e.info && e.info->unit && *e.info->unit != 0 ? hex(*e.info->unit, 8) : std::string());
    return o.finish();
}

}  // namespace

ViewValue dictionary_section(const Dictionary* dictionary, const PageContext& context) {
    if (!dictionary || dictionary->objects.empty()) return ViewValue::null();
    ViewArena& arena = *context.arena;
    const DataTypeIndex types(dictionary);
    std::vector<const Object*> objects;
    objects.reserve(dictionary->objects.size());
    for (const Object& o : dictionary->objects) objects.push_back(&o);
    std::stable_sort(objects.begin(), objects.end(), [](const Object* a, const Object* b) { return a->index < b->index; });

    ListBuilder list(arena);
    std::size_t entry_count = 0;
    for (const Object* object : objects) {
        const ObjectLayout layout = layout_of(types, *object);
        PageObject o(arena);
        o.add("index_hex", hex(object->index, 4));
        o.add("name", context.text(object->names));
        o.add("code", ViewValue::of_static(to_string(layout.code)));
        o.add("type", object->type);
        o.add("bit_size", object->bit_size);
        const bool is_var = layout.code == ObjectCode::var && layout.entries.size() == 1;
        const std::string& name = context.text(object->names);
        o.add("var", is_var ? entry_view(layout.entries.front(), name, types, context) : ViewValue::null());
        ListBuilder entries(arena);
        if (!is_var)
            for (const ObjectEntry& e : layout.entries) entries.add(entry_view(e, e.name, types, context));
        entry_count += is_var ? 1 : layout.entries.size();
        o.add("entries", entries.finish());
        list.add(o.finish());
    }
    PageObject section(arena);
    section.add("object_count", objects.size());
    section.add("entry_count", entry_count);
    section.add("count_text", counted(objects.size(), "object") + ", " + counted(entry_count, "entry", "entries"));
    section.add("objects", list.finish());
    return section.finish();
}

}  // namespace esi::doc
