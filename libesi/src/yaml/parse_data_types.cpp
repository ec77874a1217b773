// `data_types:` of the object dictionary: explicit DataType elements (records and arrays with
// their SubItems, enumerations with their values), keyed by name.

#include "esi/derive/object_builder.hpp"
#include "yaml/extras.hpp"
#include "yaml/source_parser.hpp"

namespace esi::yaml {

// An enum value's text: `1: On`, or `1: {text: On, comment: ...}`. False when the mapping form
// is broken (already reported).
bool SourceParser::enum_texts(const Node& value, EnumValue& ev) {
    if (!value.IsMap()) {
        ev.texts = r_.names(value, "enum text");
        return true;
    }
    const auto ef = r_.mapping(value, Context::enum_value, "an enum value");
    if (!ef) return false;
    ev.texts = names_of(*ef, "text");
    ev.comments = names_of(*ef, "comment");
    return true;
}

std::optional<DataType> SourceParser::data_type(const Node& node) {
    const auto f = r_.mapping(node, Context::data_type, "a data type");
    if (!f) return std::nullopt;
    DataType t;
    t.pos = f->pos();
    if (!r_.require(*f, "name", "a data type")) return std::nullopt;
    t.name = r_.text(*f->find("name"), "name").value_or("");
    t.name_pos = pos_of(*f->find("name"));
    r_.optional_integer<std::uint32_t>(*f, "index", t.index, 0, 0xFFFF);
    r_.optional_text(*f, "base_type", t.base_type);
    if (const Node* n = f->find("bit_size")) t.bit_size = r_.integer<std::uint64_t>(*n, "bit_size", 0, 0xFFFFFFFF).value_or(0);
    t.comments = names_of(*f, "comment");
    if (const Node* n = f->find("array")) {
        std::vector<Node> dims;
        if (n->IsSequence())
            for (const auto& d : *n) dims.push_back(d);
        else
            dims.push_back(*n);
        for (const auto& d : dims) {
            const auto af = r_.mapping(d, Context::array_info, "array");
            if (!af || !r_.require(*af, "elements", "array")) continue;
            ArrayInfo ai;
            ai.pos = af->pos();
            ai.elements = r_.integer<std::int64_t>(*af->find("elements"), "elements", 0, 0xFFFF).value_or(0);
            if (const Node* lb = af->find("lower_bound")) ai.lower_bound = r_.integer<std::int64_t>(*lb, "lower_bound", 0, 0xFFFF).value_or(0);
            t.array_info.push_back(ai);
        }
    }
    if (const Node* n = f->find("sub_items")) {
        if (auto items = r_.sequence(*n, "sub_items")) {
            Dictionary scratch;  // sub-item values are typed by basic types or types declared before this one
            std::uint64_t offset = 0;
            for (const auto& item : *items) {
                const auto sf = r_.mapping(item, Context::type_sub_item, "a sub-item");
                if (!sf) continue;
                DataTypeSubItem s;
                s.pos = sf->pos();
                r_.optional_integer<std::uint32_t>(*sf, "subindex", s.subindex, 0, 255);
                if (r_.require(*sf, "name", "a sub-item")) s.name = r_.text(*sf->find("name"), "name").value_or("");
                if (r_.require(*sf, "type", "a sub-item")) s.type = r_.text(*sf->find("type"), "type").value_or("");
                s.display_names = names_of(*sf, "display_name");
                s.comments = names_of(*sf, "comment");
                if (const Node* b = sf->find("bit_size")) s.bit_size = r_.integer<std::uint64_t>(*b, "bit_size", 0, 0xFFFFFFFF).value_or(0);
                else s.bit_size = implied_bit_size(s.type).value_or(0);
                if (const Node* b = sf->find("bit_offset")) s.bit_offset = r_.integer<std::uint64_t>(*b, "bit_offset", 0, 0xFFFFFFFF).value_or(0);
                else s.bit_offset = offset;
                offset = s.bit_offset + s.bit_size;
                const ValueType vt = value_type_of(scratch, s.type);
                if (const Node* d = sf->find("default")) {
                    if (vt.basic && vt.basic->type_class == TypeClass::visible_string) s.default_string = r_.text(*d, "default");
                    else s.default_value = typed_integer(*d, scratch, s.type, "default");
                }
                if (const Node* d = sf->find("min")) s.min_value = typed_integer(*d, scratch, s.type, "min");
                if (const Node* d = sf->find("max")) s.max_value = typed_integer(*d, scratch, s.type, "max");
                if (const Node* d = sf->find("default_data")) s.default_data = r_.hex(*d, "default_data");
                if (const Node* d = sf->find("default_string")) s.default_string = r_.text(*d, "default_string");
                s.flags = flags(*sf);
                extras(*sf, "xml", s.extras);
                t.sub_items.push_back(std::move(s));
            }
            if (t.bit_size == 0 && !f->has("bit_size")) t.bit_size = (offset + 7) / 8 * 8;
        }
    }
    if (const Node* n = f->find("enum")) {
        if (!n->IsMap()) {
            r_.error(*n, "yaml-type", "'enum' maps values to texts: {0: Off, 1: On}");
        } else {
            for (auto it = n->begin(); it != n->end(); ++it) {
                EnumValue ev;
                ev.pos = pos_of(it->first);
                ev.value = r_.number(it->first, "enum value").value_or(Number{});
                if (!enum_texts(it->second, ev)) continue;
                t.enums.push_back(std::move(ev));
            }
        }
    }
    if (t.bit_size == 0 && !f->has("bit_size")) {
        if (!t.array_info.empty() && t.base_type) {
            std::uint64_t count = 1;
            for (const auto& ai : t.array_info) count *= static_cast<std::uint64_t>(std::max<std::int64_t>(ai.elements, 0));
            t.bit_size = count * implied_bit_size(*t.base_type).value_or(0);
        } else if (t.base_type) {
            t.bit_size = implied_bit_size(*t.base_type).value_or(0);
        } else {
            t.bit_size = implied_bit_size(t.name).value_or(0);
        }
    }
    extras(*f, "xml", t.extras);
    return t;
}

}  // namespace esi::yaml
