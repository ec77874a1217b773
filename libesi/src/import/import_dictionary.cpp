// The object dictionary: `data_types:` and `objects:`, without what derivation writes again for
// the device under the plan. Integer values are written typed when the parser reads them back the
// same, else as their bytes.

#include <algorithm>
#include <set>

#include "esi/model/typed_value.hpp"
#include "esi/model/object_layout.hpp"
#include "import/import_writer.hpp"

namespace esi::import_detail {

namespace {

std::string num(const Number& n) { return format_decimal(n); }

ValueType value_type(const Dictionary* d, const std::string& type_name) {
    ValueType t;
    t.name = type_name;
    const ResolvedType r = resolve_type(d, type_name);
    t.basic = r.basic;
    t.bit_size = r.bit_size;
    if (r.definition && !r.definition->enums.empty()) t.enumeration = r.definition;
    return t;
}

// The value as the parser types it (`default: 5` for an integer type), when it reads back the same.
bool typed_fits(const Number& n, const ValueType& t) {
    SourceValue v;
    v.kind = SourceValue::Kind::integer;
    v.integer = n;
    std::string error;
    const auto back = integer_value(v, t, error);
    return back && *back == n;
}

HexData bytes_of(const Number& n, std::uint64_t bit_size) {
    std::size_t count = static_cast<std::size_t>((bit_size + 7) / 8);
    if (count == 0 || count > 8) count = 8;
    std::vector<std::uint8_t> bytes;
    const std::uint64_t pattern = n.bits();
    for (std::size_t i = 0; i < count; ++i) bytes.push_back(static_cast<std::uint8_t>(pattern >> (8 * i)));
    return HexData::from_bytes(bytes);
}

}  // namespace

void ImportWriter::flags(YNode& m, const ObjectFlags& f, const std::string& path, std::string_view xml_key) {
    if (f.access) {
        if (*f.access == "ro" || *f.access == "rw" || *f.access == "wo") m.set("access", YNode::text(*f.access));
        else warn(child(path, "Flags/Access"), "'" + *f.access + "' is not ro, rw or wo; dropped");
    }
    if (f.access_read_restrictions) m.set("read_restrictions", YNode::text(*f.access_read_restrictions));
    if (f.access_write_restrictions) m.set("write_restrictions", YNode::text(*f.access_write_restrictions));
    if (f.pdo_mapping) {
        static constexpr std::string_view known[] = {"R", "T", "RT", "TR", "r", "t", "rt", "tr"};
        if (std::find(std::begin(known), std::end(known), *f.pdo_mapping) != std::end(known))
            m.set("pdo", YNode::text(*f.pdo_mapping));
        else
            warn(child(path, "Flags/PdoMapping"), "'" + *f.pdo_mapping + "' is not R, T, RT or TR; dropped");
    }
    if (f.category) {
        if (*f.category == "m" || *f.category == "o" || *f.category == "c") m.set("category", YNode::text(*f.category));
        else warn(child(path, "Flags/Category"), "'" + *f.category + "' is not m, o or c; dropped");
    }
    if (f.backup) m.set("backup", YNode::integer(*f.backup));
    if (f.setting) m.set("setting", YNode::integer(*f.setting));
    if (f.safety_mapping) m.set("safety_mapping", YNode::text(*f.safety_mapping));
    if (f.attribute) m.set("attribute", YNode::hex(*f.attribute, 2));
    if (f.transition) m.set("transition", YNode::text(*f.transition));
    if (f.sdo_access) m.set("sdo_access", YNode::text(*f.sdo_access));
    set_extras(m, xml_key, f.extras);
}

// Info values. An integer value is written typed (`default: 5`) when the parser reads it back the
// same; otherwise (out of the type's range, a type that is not an integer) as its little-endian
// bytes, which esi-diff compares equal (CoE transfers values little-endian, ETG.1000.6).
void ImportWriter::info(YNode& m, const ObjectInfo& i, const Dictionary* d, const std::string& type, const std::string& path,
                        bool typed_limits) {
    const ValueType vt = value_type(d, type);
    const bool integer = vt.basic && vt.basic->is_integer();
    auto value = [&](const char* key, const char* data_key, const std::optional<Number>& n, const std::optional<HexData>& data) {
        if (n && data) {
            warn(path, std::string("both ") + key + " value and data; the value is dropped");
        } else if (n) {
            if (!typed_limits) m.set(key, YNode::raw(num(*n)));  // info_sub_items: untyped
            else if (integer && typed_fits(*n, vt)) m.set(key, YNode::raw(num(*n)));
            else m.set(data_key, hex_data(bytes_of(*n, vt.bit_size)));
            return;
        }
        if (data) {
            if (valid_hex(*data)) m.set(data_key, hex_data(*data));
            else warn(path, std::string(data_key) + " '" + data->text + "' is not hex bytes; dropped");
        }
    };
    if (i.default_string && (i.default_value || i.default_data)) warn(path, "a default string next to a default value; the string is kept");
    if (i.default_string) m.set("default_string", YNode::text(*i.default_string));
    else value("default", "default_data", i.default_value, i.default_data);
    value("min", "min_data", i.min_value, i.min_data);
    value("max", "max_data", i.max_value, i.max_data);
    if (i.display_name) m.set("display_name", YNode::text(*i.display_name));
    if (i.unit) m.set("unit", YNode::hex(*i.unit, 8));
    set_extras(m, "info_xml", i.extras);
}

YNode ImportWriter::data_type(const DataType& t, const std::string& path) {
    const std::string p = path + "/DataType[" + t.name + "]";
    YNode m = YNode::map();
    m.set("name", YNode::text(t.name));
    if (t.index) m.set("index", YNode::hex(*t.index, 4));
    if (t.base_type) m.set("base_type", YNode::text(*t.base_type));
    m.set("bit_size", YNode::unsigned_integer(t.bit_size));
    names(m, "comment", t.comments, p);
    if (!t.array_info.empty()) {
        YNode arrays = YNode::seq();
        for (const auto& a : t.array_info) {
            YNode x = YNode::map();
            x.set("lower_bound", YNode::integer(a.lower_bound));
            x.set("elements", YNode::integer(a.elements));
            arrays.push(std::move(x));
        }
        m.set("array", std::move(arrays));
    }
    if (!t.sub_items.empty()) {
        YNode items = YNode::seq();
        static const Dictionary no_types;  // sub-item values are typed by basic types only (parse_dictionary.cpp)
        for (const auto& s : t.sub_items) {
            const std::string sp = p + "/SubItem[" + s.name + "]";
            YNode x = YNode::map();
            if (s.subindex) x.set("subindex", YNode::unsigned_integer(*s.subindex));
            x.set("name", YNode::text(s.name));
            x.set("type", YNode::text(s.type));
            x.set("bit_size", YNode::unsigned_integer(s.bit_size));
            x.set("bit_offset", YNode::unsigned_integer(s.bit_offset));
            names(x, "display_name", s.display_names, sp);
            names(x, "comment", s.comments, sp);
            const ValueType vt = value_type(&no_types, s.type);
            const bool integer = vt.basic && vt.basic->is_integer();
            const bool text = vt.basic && vt.basic->type_class == TypeClass::visible_string;
            if (s.default_value && (s.default_data || s.default_string)) warn(sp, "a default value next to default data; the value is dropped");
            if (s.default_value && !s.default_data && !s.default_string) {
                if (integer && typed_fits(*s.default_value, vt)) x.set("default", YNode::raw(num(*s.default_value)));
                else x.set("default_data", hex_data(bytes_of(*s.default_value, s.bit_size)));
            }
            if (s.default_data && s.default_string) warn(sp, "default data next to a default string; the data is dropped");
            if (s.default_string) {
                if (text) x.set("default", YNode::text(*s.default_string));
                else x.set("default_string", YNode::text(*s.default_string));
            } else if (s.default_data) {
                x.set("default_data", hex_data(*s.default_data));
            }
            for (auto [key, value] : {std::pair{"min", &s.min_value}, std::pair{"max", &s.max_value}}) {
                if (!*value) continue;
                if (integer && typed_fits(**value, vt)) x.set(key, YNode::raw(num(**value)));
                else warn(sp, std::string(key) + " " + num(**value) + " cannot be typed by '" + s.type + "'; dropped");
            }
            if (s.flags) flags(x, *s.flags, sp, "flags_xml");
            set_extras(x, "xml", s.extras);
            items.push(std::move(x));
        }
        m.set("sub_items", std::move(items));
    }
    if (!t.enums.empty()) {
        YNode e = YNode::map();
        std::set<std::string> seen;
        for (const auto& ev : t.enums) {
            const std::string key = num(ev.value);
            if (!seen.insert(key).second) {
                warn(p, "enum value " + key + " twice; the second is dropped");
                continue;
            }
            YNode v = YNode::map();
            names(v, "text", ev.texts, p);
            names(v, "comment", ev.comments, p);
            if (ev.comments.empty() && ev.texts.size() == 1 && !ev.texts.front().lcid) e.set_raw_key(key, YNode::text(ev.texts.front().text));
            else e.set_raw_key(key, std::move(v));
        }
        m.set("enum", std::move(e));
    }
    set_extras(m, "xml", t.extras);
    return m;
}

YNode ImportWriter::object(const Object& o, const Dictionary& d, const std::string& path) {
    const std::string p = path + "/Object[" + hex_text(o.index, 4) + "]";
    YNode m = YNode::map();
    names(m, "name", o.names, p, true);
    names(m, "comment", o.comments, p);
    if (o.type.empty()) warn(p, "no type; the YAML format requires one");
    m.set("type", YNode::text(o.type));
    m.set("bit_size", YNode::unsigned_integer(o.bit_size));
    if (o.index_depend_on_slot) m.set("index_depend_on_slot", YNode::boolean(*o.index_depend_on_slot));
    if (o.index_depend_on_slot_group) m.set("index_depend_on_slot_group", YNode::boolean(*o.index_depend_on_slot_group));
    if (o.index_overwritten_by_module) m.set("index_overwritten_by_module", YNode::boolean(*o.index_overwritten_by_module));
    if (o.flags) flags(m, *o.flags, p, "flags_xml");
    if (o.info) {
        info(m, *o.info, &d, o.type, p + "/Info", true);
        if (!o.info->sub_items.empty()) {
            // Object/Info/SubItem as written (names and values), in order: esi-diff matches them
            // to sub-entries the way the file did.
            YNode items = YNode::seq();
            for (const auto& s : o.info->sub_items) {
                YNode x = YNode::map();
                x.set("name", YNode::text(s.name));
                if (!s.info.sub_items.empty()) warn(p + "/Info/SubItem[" + s.name + "]", "nested SubItems are dropped");
                info(x, s.info, &d, "", p + "/Info/SubItem[" + s.name + "]", false);
                set_extras(x, "xml", s.extras);
                items.push(std::move(x));
            }
            m.set("info_sub_items", std::move(items));
        }
    }
    set_extras(m, "xml", o.extras);
    return m;
}

namespace {

// The objects derivation writes for a device under `plan` (docs/yaml-format.md, Derivation).
bool derived_object(const Object& o, const Device* device, const OmitPlan& plan) {
    if (!device) return false;
    if (o.index == 0x1000) return plan.device_type_object;
    if (o.index == 0x1018) return plan.identity_object;
    if (o.index == 0x1C00) return plan.sm_types_object;
    if (o.index >= 0x1C10 && o.index < 0x1C10 + std::min<std::size_t>(device->sms.size(), 16)) return plan.assignment_objects;
    if (plan.mapping_objects)
        for (const auto* pdos : {&device->rx_pdos, &device->tx_pdos})
            for (const auto& p : *pdos)
                if (p.index == o.index) return true;
    return false;
}

}  // namespace

void ImportWriter::dictionary(YNode& m, const Dictionary& d, const std::string& path, const OmitPlan& plan, const Device* device) {
    // Types only derived objects name go with them (derivation declares them again); a type named
    // like a basic type goes when DataTypes are derived. The plan was checked by deriving.
    std::set<std::string> kept_names, omitted_names;
    for (const auto& o : d.objects) (derived_object(o, device, plan) ? omitted_names : kept_names).insert(o.type);
    // Follow BaseType and SubItem types: DT1C12 names DT1C12ARR, which goes (or stays) with it.
    auto close = [&](std::set<std::string>& names) {
        for (bool grew = true; grew;) {
            grew = false;
            for (const auto& t : d.data_types) {
                if (!names.count(t.name)) continue;
                if (t.base_type) grew = names.insert(*t.base_type).second || grew;
                for (const auto& s : t.sub_items) grew = names.insert(s.type).second || grew;
            }
        }
    };
    close(kept_names);
    close(omitted_names);
    auto omitted_type = [&](const DataType& t) {
        if (!device) return false;
        if (plan.data_types && esi::find_basic_type(t.name)) return true;
        return omitted_names.count(t.name) && !kept_names.count(t.name);
    };
    YNode types = YNode::seq();
    std::set<std::string> seen;
    for (const auto& t : d.data_types) {
        if (!seen.insert(t.name).second) {
            warn(path + "/DataType[" + t.name + "]", "declared twice; the second is dropped");
            continue;
        }
        if (omitted_type(t)) continue;
        types.push(data_type(t, path));
    }
    if (!types.empty()) m.set("data_types", std::move(types));
    YNode objects = YNode::map();
    std::set<std::uint32_t> seen_objects;
    for (const auto& o : d.objects) {
        if (!seen_objects.insert(o.index).second) {
            warn(path + "/Object[" + hex_text(o.index, 4) + "]", "declared twice; the second is dropped");
            continue;
        }
        if (derived_object(o, device, plan)) continue;
        objects.set_raw_key(hex_text(o.index, 4), object(o, d, path));
    }
    m.set("objects", std::move(objects));
    set_extras(m, "dictionary_xml", d.extras);
}

}  // namespace esi::import_detail
