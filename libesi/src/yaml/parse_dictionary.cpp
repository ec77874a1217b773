// The object dictionary: `data_types:` (explicit DataType elements) and `objects:` keyed by
// index. An object is a VAR (type), an ARRAY (type + array: n) or a RECORD (entries: keyed by
// sub-index); the object code follows from which keys are written, never from the shape of the
// values: a generator that inferred ARRAY or RECORD from the shape of the sub-entries guessed wrong
// where both readings fit.
// Defaults, minima and maxima are typed by the object: an integer type takes a number (or an
// enumeration text), REAL/LREAL a number stored as DefaultData, STRING(n) a text. The DataTypes
// are read in parse_data_types.cpp.

#include <algorithm>
#include <cstdio>
#include <set>

#include "esi/derive/object_builder.hpp"
#include "esi/model/object_layout.hpp"
#include "yaml/extras.hpp"
#include "yaml/source_parser.hpp"
#include "yaml/type_names.hpp"

namespace esi::yaml {

namespace {

std::string type_name_for(std::uint32_t index) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "DT%04X", index);
    return buffer;
}

constexpr std::string_view info_keys[] = {"default", "min", "max", "default_data", "min_data", "max_data", "default_string",
                                          "display_name", "unit", "info_xml"};
constexpr std::string_view flag_keys[] = {"access", "read_restrictions", "write_restrictions", "pdo", "category", "backup",
                                          "setting", "safety_mapping", "attribute", "transition", "sdo_access", "flags_xml"};

}  // namespace

ValueType value_type_of(const Dictionary& dictionary, const std::string& type_name) {
    ValueType t;
    t.name = type_name;
    const ResolvedType resolved = resolve_type(&dictionary, type_name);
    t.basic = resolved.basic;
    t.bit_size = resolved.bit_size;
    if (resolved.definition && !resolved.definition->enums.empty()) t.enumeration = resolved.definition;
    return t;
}

std::optional<ObjectFlags> SourceParser::flags(const Fields& f) {
    ObjectFlags flags;
    bool any = false;
    for (auto k : flag_keys) any = any || f.has(k);
    if (!any) return std::nullopt;
    flags.pos = f.pos();
    if (const Node* n = f.find("access")) {
        if (auto a = r_.text(*n, "access")) {
            if (*a == "ro" || *a == "rw" || *a == "wo") flags.access = *a;
            else r_.error(*n, "yaml-value", "'access' is ro, rw or wo, not '" + *a + "'");
        }
    }
    r_.optional_text(f, "read_restrictions", flags.access_read_restrictions);
    r_.optional_text(f, "write_restrictions", flags.access_write_restrictions);
    if (const Node* n = f.find("pdo")) {
        if (auto p = r_.text(*n, "pdo")) {
            static const std::pair<std::string_view, std::string_view> spellings[] = {
                {"rx", "R"}, {"tx", "T"}, {"rxtx", "RT"}, {"txrx", "TR"}, {"R", "R"}, {"T", "T"}, {"RT", "RT"},
                {"TR", "TR"}, {"r", "r"}, {"t", "t"}, {"rt", "rt"}, {"tr", "tr"}};
            bool found = false;
            for (const auto& [yaml, esi] : spellings)
                if (*p == yaml) {
                    flags.pdo_mapping = std::string(esi);
                    found = true;
                }
            if (!found && *p != "none")
                r_.error(*n, "yaml-value", "'pdo' is rx, tx, rxtx or none (which PDOs may map the object), not '" + *p + "'");
        }
    }
    if (const Node* n = f.find("category")) {
        if (auto c = r_.text(*n, "category")) {
            if (*c == "m" || *c == "o" || *c == "c") flags.category = *c;
            else r_.error(*n, "yaml-value", "'category' is m (mandatory), o (optional) or c (conditional), not '" + *c + "'");
        }
    }
    r_.optional_integer(f, "backup", flags.backup);
    r_.optional_integer(f, "setting", flags.setting);
    r_.optional_text(f, "safety_mapping", flags.safety_mapping);
    r_.optional_integer(f, "attribute", flags.attribute);
    r_.optional_text(f, "transition", flags.transition);
    r_.optional_text(f, "sdo_access", flags.sdo_access);
    extras(f, "flags_xml", flags.extras);
    return flags;
}

std::optional<Number> SourceParser::typed_integer(const Node& node, const Dictionary& dictionary, const std::string& type_name,
                                                  std::string_view what) {
    const auto v = r_.scalar_value(node, what);
    if (!v) return std::nullopt;
    std::string error;
    const auto n = integer_value(*v, value_type_of(dictionary, type_name), error);
    if (!n) r_.error(node, v->kind == SourceValue::Kind::integer ? "yaml-number-range" : "yaml-type", "'" + std::string(what) + "': " + error);
    return n;
}

std::optional<ObjectInfo> SourceParser::info(const Fields& f, const Dictionary& dictionary, const std::string& type_name,
                                             std::string_view what) {
    bool any = false;
    for (auto k : info_keys) any = any || f.has(k);
    if (!any) return std::nullopt;
    ObjectInfo info;
    info.pos = f.pos();
    const ValueType type = value_type_of(dictionary, type_name);
    const bool integer = type.basic && type.basic->is_integer();
    const bool real = type.basic && type.basic->type_class == TypeClass::real;
    const bool text = type.basic && type.basic->type_class == TypeClass::visible_string;

    auto typed = [&](std::string_view key, RareOptional<Number>& number, auto& data, RareOptional<std::string>* str) {
        const Node* n = f.find(key);
        if (!n) return;
        if (integer) {
            number = typed_integer(*n, dictionary, type_name, key);
        } else if (real) {
            if (const auto v = r_.scalar_value(*n, key)) {
                const EncodedValue e = encode_value(*v, type);
                if (e.ok()) data = HexData::from_bytes(e.bytes);
                else r_.error(*n, "yaml-type", "'" + std::string(key) + "': " + e.error);
            }
        } else if (text && str) {
            if (auto s = r_.text(*n, key)) {
                SourceValue v;
                v.text = *s;
                const EncodedValue e = encode_value(v, type);
                if (e.ok()) *str = *s;
                else r_.error(*n, "yaml-value", "'" + std::string(key) + "': " + e.error);
            }
        } else {
            r_.error(*n, "yaml-type",
                     "'" + std::string(key) + "' cannot be typed for '" + type_name + "' in " + std::string(what) + "; give '" +
                         std::string(key) + "_data' (hex bytes) instead");
        }
    };
    typed("default", info.default_value, info.default_data, &info.default_string);
    typed("min", info.min_value, info.min_data, nullptr);
    typed("max", info.max_value, info.max_data, nullptr);
    auto raw = [&](std::string_view key, std::string_view typed_key, auto& data) {
        const Node* n = f.find(key);
        if (!n) return;
        if (f.has(typed_key))
            r_.error(*f.key_node(key), "yaml-conflict",
                     "give either '" + std::string(typed_key) + "' or '" + std::string(key) + "', not both (one home per value)");
        data = r_.hex(*n, key);
    };
    raw("default_data", "default", info.default_data);
    raw("min_data", "min", info.min_data);
    raw("max_data", "max", info.max_data);
    if (const Node* n = f.find("default_string")) {
        if (f.has("default") || f.has("default_data"))
            r_.error(*f.key_node("default_string"), "yaml-conflict", "give one of 'default', 'default_data' and 'default_string'");
        info.default_string = r_.text(*n, "default_string");
    }
    r_.optional_text(f, "display_name", info.display_name);
    r_.optional_integer(f, "unit", info.unit);
    extras(f, "info_xml", info.extras);
    return info;
}

// Object/Info/SubItem as written, matched to the sub-entries by position and name the way the
// ESI file did (object_layout.cpp). The importer writes this form; values are untyped numbers or
// hex bytes because the sub-entry they belong to is only known once the layout is built.
std::optional<ObjectSubItemInfo> SourceParser::info_sub_item(const Node& node) {
    const auto f = r_.mapping(node, Context::info_sub_item, "an info sub-item");
    if (!f) return std::nullopt;
    ObjectSubItemInfo s;
    s.pos = s.info.pos = f->pos();
    if (r_.require(*f, "name", "an info sub-item")) s.name = r_.text(*f->find("name"), "name").value_or("");
    auto value = [&](std::string_view key, std::string_view data_key, RareOptional<Number>& number, auto& data) {
        if (const Node* n = f->find(key)) number = r_.number(*n, key);
        if (const Node* n = f->find(data_key)) {
            if (f->has(key))
                r_.error(*f->key_node(data_key), "yaml-conflict",
                         "give either '" + std::string(key) + "' or '" + std::string(data_key) + "', not both (one home per value)");
            data = r_.hex(*n, data_key);
        }
    };
    value("default", "default_data", s.info.default_value, s.info.default_data);
    value("min", "min_data", s.info.min_value, s.info.min_data);
    value("max", "max_data", s.info.max_value, s.info.max_data);
    r_.optional_text(*f, "default_string", s.info.default_string);
    r_.optional_text(*f, "display_name", s.info.display_name);
    r_.optional_integer(*f, "unit", s.info.unit);
    extras(*f, "info_xml", s.info.extras);
    extras(*f, "xml", s.extras);
    return s;
}

void SourceParser::object(const Node& key, const Node& value, Dictionary& dictionary,
                          std::map<std::uint32_t, std::pair<SourcePos, std::string>>& seen) {
    Object o;
    o.pos = o.index_pos = pos_of(key);
    const auto index = r_.integer<std::uint32_t>(key, "object index", 0, 0xFFFF);
    if (!index) return;
    o.index = *index;
    if (const auto [it, inserted] = seen.emplace(o.index, std::pair{o.pos, key.Scalar()}); !inserted) {
        // The same text twice is already a duplicate key; 0x6000 and 24576 are one index too.
        if (it->second.second != key.Scalar()) {
            Diagnostic& d = r_.error(key, "yaml-duplicate-key", "object " + hex4(o.index) + " is declared twice");
            d.notes.push_back({r_.path(), it->second.first, "first declared here"});
        }
        return;
    }
    const auto f = r_.mapping(value, Context::object, "object " + hex4(o.index));
    if (!f) return;
    const std::string what = "object " + hex4(o.index);
    if (r_.require(*f, "name", what)) o.names = names_of(*f, "name");
    o.comments = names_of(*f, "comment");
    r_.optional_bool(*f, "index_depend_on_slot", o.index_depend_on_slot);
    r_.optional_bool(*f, "index_depend_on_slot_group", o.index_depend_on_slot_group);
    r_.optional_bool(*f, "index_overwritten_by_module", o.index_overwritten_by_module);
    o.flags = flags(*f);
    std::string type;
    if (const Node* n = f->find("type")) {
        type = r_.text(*n, "type").value_or("");
        o.type_pos = pos_of(*n);
        if (const std::string misspelt = misspelt_type_message(type, dictionary); !misspelt.empty()) {
            r_.error(*n, "yaml-type", misspelt);
            return;
        }
    }
    const bool is_array = f->has("array");
    const bool has_entries = f->has("entries");
    const bool has_enum = f->has("enum");
    std::string error;

    auto reject_object_values = [&](std::string_view why) {
        for (auto k : {"default", "min", "max", "default_data", "min_data", "max_data", "default_string"})
            if (f->has(k)) r_.error(*f->key_node(k), "yaml-conflict", std::string(why));
    };

    if (is_array || has_entries) {
        if (has_enum) r_.error(*f->key_node("enum"), "yaml-conflict", "'enum' belongs to a VAR object (or a declared data type)");
        reject_object_values("values of an ARRAY or RECORD are given per sub-index under 'entries'");
    }

    if (is_array) {
        const auto count = r_.integer<std::uint32_t>(*f->find("array"), "array", 1, 255);
        if (!r_.require(*f, "type", what + " (an ARRAY names its element type)") || !count) return;
        std::vector<std::optional<ObjectInfo>> infos(*count + 1u);
        std::vector<std::string> element_names(*count + 1u);
        if (const Node* n = f->find("entries")) {
            if (!n->IsMap()) {
                r_.error(*n, "yaml-type", "'entries' maps sub-indices to their values: {1: {default: 0x1600}}");
            } else {
                for (auto it = n->begin(); it != n->end(); ++it) {
                    const auto sub = r_.integer<std::uint32_t>(it->first, "sub-index", 0, *count);
                    const auto ef = r_.mapping(it->second, Context::object_entry, "an array element");
                    if (!sub || !ef) continue;
                    for (const auto& item : ef->items())
                        if (item.key != "name" && std::find(std::begin(info_keys), std::end(info_keys), item.key) == std::end(info_keys))
                            r_.error(item.key_node, "yaml-conflict",
                                     "array elements share the array's type and flags; '" + std::string(item.key) + "' cannot differ per element");
                    if (const Node* nm = ef->find("name")) element_names[*sub] = r_.text(*nm, "name").value_or("");
                    infos[*sub] = info(*ef, dictionary, *sub == 0 ? std::string("USINT") : type, "an array element");
                }
            }
        }
        const std::string type_name = unique_type_name(dictionary, type_name_for(o.index));
        error = build_array(dictionary, o, type_name, type, *count, std::move(infos), o.flags, o.flags, std::move(element_names));
    } else if (has_entries) {
        const Node& entries = *f->find("entries");
        if (!entries.IsMap()) {
            r_.error(entries, "yaml-type", "'entries' maps sub-indices to sub-entries: {1: {name: Kp, type: REAL}}");
            return;
        }
        const DataType* declared = type.empty() ? nullptr : dictionary.find_data_type(type);
        if (!type.empty()) {
            // A declared structured type: the entries give values only.
            if (!declared || declared->sub_items.empty()) {
                r_.error(*f->find("type"), "yaml-type",
                         "'" + type + "' is not a record type declared in data_types; drop 'type' to generate the record from 'entries'");
                return;
            }
            ObjectInfo object_info;
            object_info.pos = f->pos();
            Object probe;
            probe.type = type;
            const ObjectLayout layout = layout_of(&dictionary, probe);
            for (auto it = entries.begin(); it != entries.end(); ++it) {
                const auto sub = r_.integer<std::uint32_t>(it->first, "sub-index", 0, 255);
                const auto ef = r_.mapping(it->second, Context::object_entry, "an entry");
                if (!sub || !ef) continue;
                const ObjectEntry* le = layout.entry(*sub);
                if (!le) {
                    r_.error(it->first, "yaml-reference", "the type '" + type + "' has no sub-index " + std::to_string(*sub));
                    continue;
                }
                for (const auto& field : ef->items())
                    if (std::find(std::begin(info_keys), std::end(info_keys), field.key) == std::end(info_keys))
                        r_.error(field.key_node, "yaml-conflict",
                                 "'" + std::string(field.key) + "' is defined by the data type '" + type + "'; entries of such an object give values only");
                ObjectSubItemInfo si;
                si.name = le->name;
                si.pos = ef->pos();
                if (auto i = info(*ef, dictionary, le->type, "an entry")) si.info = std::move(*i);
                object_info.sub_items.push_back(std::move(si));
            }
            o.type = type;
            o.bit_size = declared->bit_size;
            o.info = std::move(object_info);
        } else {
            std::vector<RecordEntry> records;
            std::set<std::uint32_t> subs;
            bool misspelt_type = false;  // reported at the entry; the record is not built
            for (auto it = entries.begin(); it != entries.end(); ++it) {
                const auto sub = r_.integer<std::uint32_t>(it->first, "sub-index", 0, 255);
                const auto ef = r_.mapping(it->second, Context::object_entry, "an entry");
                if (!sub || !ef) continue;
                subs.insert(*sub);
                RecordEntry e;
                e.item.subindex = *sub;
                e.item.pos = ef->pos();
                if (r_.require(*ef, "name", "an entry")) e.item.name = r_.text(*ef->find("name"), "name").value_or("");
                if (r_.require(*ef, "type", "an entry")) e.item.type = r_.text(*ef->find("type"), "type").value_or("");
                if (const std::string misspelt = misspelt_type_message(e.item.type, dictionary); !misspelt.empty()) {
                    r_.error(*ef->find("type"), "yaml-type", misspelt);
                    misspelt_type = true;
                    continue;
                }
                e.item.comments = names_of(*ef, "comment");
                if (const Node* b = ef->find("bit_size")) e.item.bit_size = r_.integer<std::uint64_t>(*b, "bit_size", 1, 0xFFFF).value_or(0);
                if (const Node* b = ef->find("bit_offset")) {
                    e.item.bit_offset = r_.integer<std::uint64_t>(*b, "bit_offset", 0, 0xFFFF).value_or(0);
                    e.explicit_offset = true;
                }
                e.item.flags = flags(*ef);
                // `pdo:` on a RECORD built from its entries applies to every sub-index but the
                // count that has no `pdo` of its own (the mapping flags are per sub-index in ESI).
                if (*sub != 0 && o.flags && o.flags->pdo_mapping && !ef->has("pdo")) {
                    if (!e.item.flags) {
                        e.item.flags.emplace();
                        e.item.flags->pos = ef->pos();
                    }
                    e.item.flags->pdo_mapping = o.flags->pdo_mapping;
                }
                e.info = info(*ef, dictionary, e.item.type, "an entry");
                extras(*ef, "xml", e.item.extras);
                records.push_back(std::move(e));
            }
            if (misspelt_type) return;
            if (records.empty()) {
                r_.error(entries, "yaml-value", "a RECORD needs at least one entry");
                return;
            }
            ObjectFlags sub0_flags;
            sub0_flags.access = "ro";
            error = build_record(dictionary, o, unique_type_name(dictionary, type_name_for(o.index)), std::move(records), sub0_flags);
        }
    } else {
        if (!r_.require(*f, "type", what)) return;
        if (has_enum) {
            // ETG.2000 / ET9300 §13.5: enumerations are DataTypes DTxxxxENyy in 0x0800..0x0FFF.
            std::uint32_t next = 0x0800;
            for (const auto& t : dictionary.data_types)
                if (t.index && *t.index >= next && *t.index <= 0x0FFF) next = *t.index + 1;
            const std::uint64_t bits = type_bit_size(dictionary, type);
            const ValueType base = value_type_of(dictionary, type);
            if (!base.basic || !base.basic->is_integer() || bits == 0 || bits > 64) {
                r_.error(*f->find("type"), "yaml-type", "an enumeration needs an integer base type such as USINT, not '" + type + "'");
                return;
            }
            DataType t;
            char name[32];
            std::snprintf(name, sizeof name, "DT%04XEN%02u", next, static_cast<unsigned>(bits));
            t.index = next;
            t.name = unique_type_name(dictionary, name);
            t.base_type = type;
            t.bit_size = bits;
            t.pos = t.name_pos = pos_of(*f->find("enum"));
            const Node& en = *f->find("enum");
            if (!en.IsMap()) {
                r_.error(en, "yaml-type", "'enum' maps values to texts: {0: Off, 1: On}");
                return;
            }
            for (auto it = en.begin(); it != en.end(); ++it) {
                EnumValue ev;
                ev.pos = pos_of(it->first);
                if (auto v = typed_integer(it->first, dictionary, type, "enum value")) ev.value = *v;
                if (!enum_texts(it->second, ev)) continue;
                t.enums.push_back(std::move(ev));
            }
            dictionary.data_types.push_back(std::move(t));
            type = dictionary.data_types.back().name;
        }
        o.type = type;
        if (const Node* n = f->find("bit_size")) {
            // 0 is what some files write for STRING(0) and structured objects; kept as written.
            o.bit_size = r_.integer<std::uint64_t>(*n, "bit_size", 0, 0xFFFFFFFF).value_or(0);
            o.bit_size_pos = pos_of(*n);
        } else {
            o.bit_size = type_bit_size(dictionary, type);
            const TypeName parsed = parse_type_name(type);
            if (o.bit_size == 0 && (parsed.kind != TypeName::Kind::named || dictionary.find_data_type(type)) &&
                !(parsed.basic && parsed.basic->type_class == TypeClass::domain))
                r_.error(*f->find("type"), "yaml-type", "the type '" + type + "' has no known size; give bit_size");
        }
        o.info = info(*f, dictionary, type, what);
    }
    if (!error.empty()) {
        r_.error(o.pos, "yaml-value", what + ": " + error);
        return;
    }
    if (const Node* n = f->find("info_xml"); n && (is_array || has_entries)) {
        if (!o.info) o.info = ObjectInfo{};
        read_extras(r_, *n, o.info->extras, "info_xml");
    }
    if (is_array || has_entries) {
        if (const Node* n = f->find("display_name")) {
            if (!o.info) o.info = ObjectInfo{};
            o.info->display_name = r_.text(*n, "display_name");
        }
        if (const Node* n = f->find("unit")) {
            if (!o.info) o.info = ObjectInfo{};
            o.info->unit = r_.integer<std::uint32_t>(*n, "unit");
        }
    }
    if (const Node* n = f->find("info_sub_items")) {
        if (has_entries) r_.error(*f->key_node("info_sub_items"), "yaml-conflict", "give the sub-entries' values under 'entries' or 'info_sub_items', not both");
        else if (auto list = r_.sequence(*n, "info_sub_items")) {
            if (!o.info) {
                o.info = ObjectInfo{};
                o.info->pos = pos_of(*n);
            }
            for (const auto& item : *list)
                if (auto s = info_sub_item(item)) o.info->sub_items.push_back(std::move(*s));
        }
    }
    extras(*f, "xml", o.extras);
    dictionary.objects.push_back(std::move(o));
}

ObjectNames SourceParser::dictionary(const Fields& f, Dictionary& dictionary) {
    if (const Node* n = f.find("data_types")) {
        if (auto items = r_.sequence(*n, "data_types")) {
            for (const auto& item : *items) {
                auto t = data_type(item);
                if (!t) continue;
                if (const DataType* earlier = dictionary.find_data_type(t->name)) {
                    Diagnostic& d = r_.error(t->name_pos, "yaml-duplicate", "the data type '" + t->name + "' is declared twice");
                    d.notes.push_back({r_.path(), earlier->name_pos, "first declared here"});
                    continue;
                }
                dictionary.data_types.push_back(std::move(*t));
            }
        }
    }
    if (const Node* n = f.find("objects")) {
        if (!n->IsMap()) {
            r_.error(*n, "yaml-type", "'objects' maps object indices to objects: {0x6040: {name: Controlword, type: UINT}}");
        } else {
            std::map<std::uint32_t, std::pair<SourcePos, std::string>> seen;
            dictionary.objects.reserve(dictionary.objects.size() + n->size() + 64);  // room for the derived ones
            for (auto it = n->begin(); it != n->end(); ++it) object(it->first, it->second, dictionary, seen);
        }
    }
    extras(f, "dictionary_xml", dictionary.extras);
    return index_object_names(dictionary);
}

}  // namespace esi::yaml
