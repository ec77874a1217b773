// The model -> YAML tree: every key written here is one docs/yaml-format.md documents and the
// parser reads back into the same model field. Values the format cannot hold exactly are
// reported as warnings with their model path (the round-trip test lists them).

#include "yaml/export_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "esi/derive/typed_value.hpp"
#include "esi/model/language.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/xml_text.hpp"

namespace esi::yaml {

namespace {

std::string hex_text(std::uint64_t v, int digits) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "0x%0*llX", digits, static_cast<unsigned long long>(v));
    return buffer;
}

std::string num(const Number& n) { return format_decimal(n); }

// The language codes the parser knows (esi/model/language.hpp); any other LcId is written as a number.
std::string language_key(std::uint32_t lcid) {
    if (const auto code = language_of_lcid(lcid)) return std::string(*code);
    return std::to_string(lcid);
}

// An unmodelled element back to XML text; character data first, then the children (the model
// keeps the element's text as one string).
void xml_text(const XmlElement& e, std::string& out) {
    out += "<" + e.name;
    for (const auto& a : e.attributes) out += " " + a.name + "=\"" + xml_escaped(a.value, XmlTextKind::attribute_value) + "\"";
    if (e.text.empty() && e.children.empty()) {
        out += "/>";
        return;
    }
    out += ">";
    append_xml_escaped(out, e.text, XmlTextKind::character_data);
    for (const auto& c : e.children) xml_text(c, out);
    out += "</" + e.name + ">";
}

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

YNode hex_data(const HexData& h) { return YNode::text(h.text); }

bool valid_hex(const HexData& h) {
    if (h.text.size() % 2 != 0) return false;
    return std::all_of(h.text.begin(), h.text.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
}

YNode transitions(const std::vector<Transition>& ts) {
    if (ts.size() == 1) return YNode::text(ts.front().text);
    YNode s = YNode::seq();
    for (const auto& t : ts) s.push(YNode::text(t.text));
    return s;
}

std::string child(const std::string& path, const std::string& name) { return path.empty() ? name : path + "/" + name; }

}  // namespace

DeriveOptions OmitPlan::derive_options() const {
    DeriveOptions o = DeriveOptions::none();
    o.mailbox = data_link_layer;
    o.sync_managers = sms;
    o.fmmus = fmmus;
    o.pdo_assignment = pdo_assignment;
    o.pdo_entries = pdo_entries;
    o.device_type_object = device_type_object;
    o.identity_object = identity_object;
    o.mapping_objects = mapping_objects;
    o.assignment_objects = assignment_objects;
    o.sm_types_object = sm_types_object;
    o.data_types = data_types;
    return o;
}

void ExportWriter::warn(const std::string& path, const std::string& message) {
    if (quiet) return;
    warnings_.emplace(Severity::warning, "import-inexact", path + ": " + message, "", SourcePos{});
}

void ExportWriter::names(YNode& map, std::string_view key, const Names& ns, const std::string& path, bool required) {
    if (ns.empty()) {
        if (required) map.set(key, YNode::raw("null"));  // the key is required; null says "no Name element"
        return;
    }
    if (ns.size() == 1 && !ns.front().lcid) {
        map.set(key, YNode::text(ns.front().text));
        return;
    }
    YNode m = YNode::map();
    std::set<std::uint32_t> seen;
    for (const auto& n : ns) {
        if (!n.lcid) {
            warn(child(path, std::string(key)), "a text without LcId next to others cannot be expressed; written as LcId 1033");
        }
        const std::uint32_t lcid = n.lcid.value_or(default_lcid);
        if (!seen.insert(lcid).second) {
            warn(child(path, std::string(key)), "LcId " + std::to_string(lcid) + " twice; the second is dropped");
            continue;
        }
        m.set_raw_key(quote_text(language_key(lcid)), YNode::text(n.text));
    }
    map.set(key, std::move(m));
}

void ExportWriter::images(YNode& map, const Images& images) {
    if (images.image_data16x14) map.set("image_data", hex_data(*images.image_data16x14));
    if (images.image_file16x14) map.set("image_file", YNode::text(*images.image_file16x14));
    if (images.image16x14) map.set("image16x14", YNode::text(*images.image16x14));
}

YNode ExportWriter::extras(const Extras& e) {
    YNode x = YNode::map();
    if (!e.attributes.empty()) {
        YNode a = YNode::map();
        for (const auto& attr : e.attributes) a.set(attr.name, YNode::text(attr.value));
        x.set("attributes", std::move(a));
    }
    if (!e.elements.empty()) {
        YNode list = YNode::seq();
        for (const auto& el : e.elements) {
            std::string text;
            xml_text(el, text);
            if (el.after.empty()) {
                list.push(YNode::text(text));
            } else {
                YNode item = YNode::map();
                item.set("after", YNode::text(el.after));
                item.set("xml", YNode::text(text));
                list.push(std::move(item));
            }
        }
        x.set("elements", std::move(list));
    }
    return x;
}

void ExportWriter::set_extras(YNode& map, std::string_view key, const Extras& e) {
    if (!e.empty()) map.set(key, extras(e));
}

YNode ExportWriter::vendor(const Vendor& v) {
    YNode m = YNode::map();
    if (v.id) m.set("id", YNode::hex(*v.id, 8));
    else warn("Vendor/Id", "missing; the YAML format requires it");
    names(m, "name", v.names, "Vendor", true);
    names(m, "comment", v.comments, "Vendor");
    names(m, "url", v.urls, "Vendor");
    if (v.description_url) m.set("description_url", YNode::text(*v.description_url));
    images(m, v.images);
    if (v.unique_name) m.set("unique_name", YNode::text(*v.unique_name));
    if (v.file_version) m.set("file_version", YNode::text(*v.file_version));
    set_extras(m, "xml", v.extras);
    return m;
}

YNode ExportWriter::group(const Group& g) {
    YNode m = YNode::map();
    m.set("type", YNode::text(g.type));
    names(m, "name", g.names, "Group[" + g.type + "]", true);
    names(m, "comment", g.comments, "Group[" + g.type + "]");
    if (g.sort_order) m.set("sort_order", YNode::integer(*g.sort_order));
    if (g.parent_group) m.set("parent_group", YNode::text(*g.parent_group));
    images(m, g.images);
    set_extras(m, "xml", g.extras);
    return m;
}

YNode ExportWriter::profile(const Profile& p) {
    YNode m = YNode::map();
    if (p.profile_no) m.set("number", YNode::integer(*p.profile_no));
    if (p.add_info) m.set("add_info", YNode::integer(*p.add_info));
    if (p.channel) m.set("channel", YNode::integer(*p.channel));
    if (p.dictionary_file) m.set("dictionary_file", YNode::text(*p.dictionary_file));
    set_extras(m, "xml", p.extras);
    return m;
}

void ExportWriter::flags(YNode& m, const ObjectFlags& f, const std::string& path, std::string_view xml_key) {
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
void ExportWriter::info(YNode& m, const ObjectInfo& i, const Dictionary* d, const std::string& type, const std::string& path,
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

YNode ExportWriter::data_type(const DataType& t, const std::string& path) {
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

YNode ExportWriter::object(const Object& o, const Dictionary& d, const std::string& path) {
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

void ExportWriter::dictionary(YNode& m, const Dictionary& d, const std::string& path, const OmitPlan& plan, const Device* device) {
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

YNode ExportWriter::init_cmd(const InitCmd& c, MailboxProtocol protocol, const std::string& path) {
    YNode m = YNode::map();
    if (c.transitions.empty()) warn(path, "an InitCmd without Transition cannot be written");
    m.set("transition", transitions(c.transitions));
    if (protocol == MailboxProtocol::coe) {
        if (!c.index) warn(path, "a CoE InitCmd without Index cannot be written");
        m.set("object", YNode::hex(c.index.value_or(0), 4));
        if (c.subindex) m.set("subindex", YNode::unsigned_integer(*c.subindex));
    }
    if (protocol == MailboxProtocol::soe) {
        if (c.idn) m.set("idn", YNode::integer(*c.idn));
        if (c.channel) m.set("channel", YNode::integer(*c.channel));
    }
    if (protocol == MailboxProtocol::eoe) m.set("type", YNode::integer(c.type.value_or(0)));
    if (c.has_data) {
        if (valid_hex(c.data)) m.set("data", hex_data(c.data));
        else warn(path + "/Data", "'" + c.data.text + "' is not hex bytes; dropped");
    } else {
        warn(path, "an InitCmd without Data cannot be written; written as empty data");
        m.set("data", YNode::text(""));
    }
    if (c.comment) m.set("comment", YNode::text(*c.comment));
    if (protocol == MailboxProtocol::coe && c.complete_access) m.set("complete_access", YNode::boolean(*c.complete_access));
    if (protocol == MailboxProtocol::coe || protocol == MailboxProtocol::soe) {
        if (c.fixed) m.set("fixed", YNode::boolean(*c.fixed));
        if (c.overwritten_by_module) m.set("overwritten_by_module", YNode::boolean(*c.overwritten_by_module));
        if (c.data_adapt_automatically) m.set("adapt_automatically", YNode::boolean(*c.data_adapt_automatically));
    }
    if (protocol == MailboxProtocol::coe) {
        if (c.index_depend_on_slot) m.set("index_depend_on_slot", YNode::boolean(*c.index_depend_on_slot));
        if (c.index_depend_on_slot_group) m.set("index_depend_on_slot_group", YNode::boolean(*c.index_depend_on_slot_group));
    }
    set_extras(m, "xml", c.extras);
    return m;
}

YNode ExportWriter::mailbox(const Mailbox& mb, const Device* device, const OmitPlan& plan, const std::string& path) {
    YNode m = YNode::map();
    if (device && plan.sms) {
        // The mailbox SMs are derived from these (docs/yaml-format.md, SyncManagers).
        const SyncManager* out = nullptr;
        const SyncManager* in = nullptr;
        for (const auto& sm : device->sms) {
            if (!out && sm.type == "MBoxOut") out = &sm;
            if (!in && sm.type == "MBoxIn") in = &sm;
        }
        if (out && in && out->default_size && in->default_size && *out->default_size == *in->default_size) {
            m.set("size", YNode::unsigned_integer(*out->default_size));
        } else {
            if (out && out->default_size) m.set("out_size", YNode::unsigned_integer(*out->default_size));
            if (in && in->default_size) m.set("in_size", YNode::unsigned_integer(*in->default_size));
        }
        if (out && out->start_address && *out->start_address != 0x1000) m.set("out_address", YNode::hex(*out->start_address, 4));
        // in_address follows MBoxOut unless given (docs/yaml-format.md).
        const std::uint32_t follows = out ? out->start_address.value_or(0x1000) + out->default_size.value_or(0) : 0;
        if (in && in->start_address && (!out || *in->start_address != follows)) m.set("in_address", YNode::hex(*in->start_address, 4));
    }
    if (mb.data_link_layer && !(plan.data_link_layer && *mb.data_link_layer))
        m.set("data_link_layer", YNode::boolean(*mb.data_link_layer));
    if (mb.real_time_mode) m.set("real_time_mode", YNode::boolean(*mb.real_time_mode));
    if (mb.aoe) {
        YNode p = YNode::map();
        if (mb.aoe->ads_router) p.set("ads_router", YNode::boolean(*mb.aoe->ads_router));
        if (mb.aoe->generate_own_net_id) p.set("generate_own_net_id", YNode::boolean(*mb.aoe->generate_own_net_id));
        if (mb.aoe->initialize_own_net_id) p.set("initialize_own_net_id", YNode::boolean(*mb.aoe->initialize_own_net_id));
        if (!mb.aoe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mb.aoe->init_cmds.size(); ++i)
                list.push(init_cmd(mb.aoe->init_cmds[i], MailboxProtocol::aoe, path + "/AoE/InitCmd[" + std::to_string(i + 1) + "]"));
            p.set("init", std::move(list));
        }
        set_extras(p, "xml", mb.aoe->extras);
        m.set("aoe", std::move(p));
    }
    if (mb.eoe) {
        YNode p = YNode::map();
        if (mb.eoe->ip) p.set("ip", YNode::boolean(*mb.eoe->ip));
        if (mb.eoe->mac) p.set("mac", YNode::boolean(*mb.eoe->mac));
        if (mb.eoe->time_stamp) p.set("time_stamp", YNode::boolean(*mb.eoe->time_stamp));
        if (!mb.eoe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mb.eoe->init_cmds.size(); ++i)
                list.push(init_cmd(mb.eoe->init_cmds[i], MailboxProtocol::eoe, path + "/EoE/InitCmd[" + std::to_string(i + 1) + "]"));
            p.set("init", std::move(list));
        }
        set_extras(p, "xml", mb.eoe->extras);
        m.set("eoe", std::move(p));
    }
    if (mb.coe) {
        const CoeProtocol& c = *mb.coe;
        YNode p = YNode::map();
        auto flag = [&](const char* key, const std::optional<bool>& v) {
            if (v) p.set(key, YNode::boolean(*v));
        };
        flag("sdo_info", c.sdo_info);
        flag("pdo_assign", c.pdo_assign);
        flag("pdo_config", c.pdo_config);
        flag("pdo_upload", c.pdo_upload);
        flag("complete_access", c.complete_access);
        flag("segmented_sdo", c.segmented_sdo);
        flag("diag_history", c.diag_history);
        flag("sdo_upload_with_max_length", c.sdo_upload_with_max_length);
        flag("time_distribution", c.time_distribution);
        flag("module_od", c.module_od);
        if (c.eds_file) p.set("eds_file", YNode::text(*c.eds_file));
        if (c.ds402_channels) p.set("ds402_channels", YNode::integer(*c.ds402_channels));
        set_extras(p, "xml", c.extras);
        m.set("coe", std::move(p));
    }
    if (mb.foe) {
        YNode p = YNode::map();
        set_extras(p, "xml", mb.foe->extras);
        m.set("foe", std::move(p));
    }
    if (mb.soe) {
        YNode p = YNode::map();
        if (mb.soe->channel_count) p.set("channel_count", YNode::integer(*mb.soe->channel_count));
        if (mb.soe->drive_follows_bit3_support) p.set("drive_follows_bit3_support", YNode::boolean(*mb.soe->drive_follows_bit3_support));
        if (!mb.soe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mb.soe->init_cmds.size(); ++i)
                list.push(init_cmd(mb.soe->init_cmds[i], MailboxProtocol::soe, path + "/SoE/InitCmd[" + std::to_string(i + 1) + "]"));
            p.set("init", std::move(list));
        }
        set_extras(p, "xml", mb.soe->extras);
        m.set("soe", std::move(p));
    }
    if (mb.voe) {
        YNode p = YNode::map();
        set_extras(p, "xml", mb.voe->extras);
        m.set("voe", std::move(p));
    }
    set_extras(m, "xml", mb.extras);
    return m;
}

YNode ExportWriter::pdo_entry(const PdoEntry& e, const OmitPlan& plan, const std::string& path) {
    YNode m = YNode::map();
    if (e.index_invalid) warn(path, "an entry whose Index is not a number cannot be written");
    if (e.is_padding()) {
        if (e.bit_len == 0 || e.bit_len > 255) warn(path, "padding of " + std::to_string(e.bit_len) + " bits cannot be written");
        m.set("pad", YNode::unsigned_integer(e.bit_len));
        if (e.subindex) m.set("subindex", YNode::unsigned_integer(*e.subindex));
    } else {
        m.set("object", YNode::hex(e.index, 4));
        if (e.subindex) m.set("subindex", YNode::unsigned_integer(*e.subindex));
        if (!plan.pdo_entries && e.bit_len != 0) m.set("bit_len", YNode::unsigned_integer(e.bit_len));
    }
    if (!plan.pdo_entries || e.is_padding()) names(m, "name", e.names, path);
    if (e.comment) m.set("comment", YNode::text(*e.comment));
    if (e.data_type && (!plan.pdo_entries || e.is_padding())) m.set("data_type", YNode::text(*e.data_type));
    if (e.data_type_dscale) m.set("dscale", YNode::text(*e.data_type_dscale));
    if (e.data_type_swap_data) m.set("swap_data", YNode::text(*e.data_type_swap_data));
    if (e.fixed) m.set("fixed", YNode::boolean(*e.fixed));
    if (e.index_depend_on_slot) m.set("index_depend_on_slot", YNode::boolean(*e.index_depend_on_slot));
    if (e.index_depend_on_slot_group) m.set("index_depend_on_slot_group", YNode::boolean(*e.index_depend_on_slot_group));
    set_extras(m, "xml", e.extras);
    // The short forms of docs/yaml-format.md where they say everything: 0x6040, "0x6000:1", pad8.
    if (m.kind() == YNode::Kind::map) {
        const bool only_object = !e.is_padding() && !e.comment && !e.data_type_dscale &&
                                 !e.data_type_swap_data && !e.fixed && !e.index_depend_on_slot && !e.index_depend_on_slot_group &&
                                 e.extras.empty() && !e.index_invalid;
        if (plan.pdo_entries && only_object) {
            if (!e.subindex) return YNode::hex(e.index, 4);
            return YNode::text(hex_text(e.index, 4) + ":" + std::to_string(*e.subindex));
        }
        const bool only_pad = e.is_padding() && !e.subindex && e.names.empty() && !e.comment && !e.data_type && !e.data_type_dscale &&
                              !e.data_type_swap_data && !e.fixed && !e.index_depend_on_slot && !e.index_depend_on_slot_group &&
                              e.extras.empty() && e.bit_len > 0 && e.bit_len <= 255;
        if (only_pad) return YNode::raw("pad" + std::to_string(e.bit_len));
    }
    return m;
}

YNode ExportWriter::pdo(const Pdo& p, const OmitPlan& plan, const std::string& path) {
    const std::string pp = path + "/" + std::string(p.element_name()) + "[" + hex_text(p.index, 4) + "]";
    YNode m = YNode::map();
    if (p.index_invalid) warn(pp, "a PDO whose Index is not a number cannot be written");
    m.set("index", YNode::hex(p.index, 4));
    names(m, "name", p.names, pp);
    if (p.fixed) m.set("fixed", YNode::boolean(*p.fixed));
    if (p.mandatory) m.set("mandatory", YNode::boolean(*p.mandatory));
    if (p.is_virtual) m.set("virtual", YNode::boolean(*p.is_virtual));
    if (p.sm && !plan.pdo_assignment) m.set("sm", YNode::unsigned_integer(*p.sm));
    if (!p.sm && plan.pdo_assignment) m.set("assigned", YNode::boolean(false));
    if (p.su) m.set("su", YNode::unsigned_integer(*p.su));
    if (!p.excludes.empty()) {
        YNode list = YNode::seq();
        for (const auto& x : p.excludes) {
            if (!x.depend_on_slot && !x.depend_on_slot_group) {
                list.push(YNode::hex(x.index, 4));
                continue;
            }
            YNode xm = YNode::map();
            xm.set("index", YNode::hex(x.index, 4));
            if (x.depend_on_slot) xm.set("depend_on_slot", YNode::boolean(*x.depend_on_slot));
            if (x.depend_on_slot_group) xm.set("depend_on_slot_group", YNode::boolean(*x.depend_on_slot_group));
            list.push(std::move(xm));
        }
        m.set("exclude", std::move(list));
    }
    if (!p.excluded_sms.empty()) {
        YNode list = YNode::seq();
        for (auto s : p.excluded_sms) list.push(YNode::unsigned_integer(s));
        m.set("excluded_sms", std::move(list));
    }
    if (p.pdo_order) m.set("pdo_order", YNode::integer(*p.pdo_order));
    if (p.os_fac) m.set("os_fac", YNode::integer(*p.os_fac));
    if (p.os_min) m.set("os_min", YNode::integer(*p.os_min));
    if (p.os_max) m.set("os_max", YNode::integer(*p.os_max));
    if (p.os_index_inc) m.set("os_index_inc", YNode::integer(*p.os_index_inc));
    if (p.overwritten_by_module) m.set("overwritten_by_module", YNode::boolean(*p.overwritten_by_module));
    if (p.sra_parameter) m.set("sra_parameter", YNode::boolean(*p.sra_parameter));
    if (p.safety_pdo_type) m.set("safety_pdo_type", YNode::text(*p.safety_pdo_type));
    if (p.safety_conn_number) m.set("safety_conn_number", YNode::integer(*p.safety_conn_number));
    if (p.index_depend_on_slot) m.set("index_depend_on_slot", YNode::boolean(*p.index_depend_on_slot));
    if (p.index_depend_on_slot_group) m.set("index_depend_on_slot_group", YNode::boolean(*p.index_depend_on_slot_group));
    if (p.entries.size() > 254) warn(pp, "more than 254 entries cannot be written");
    YNode entries = YNode::seq();
    for (std::size_t i = 0; i < p.entries.size(); ++i)
        entries.push(pdo_entry(p.entries[i], plan, pp + "/Entry[" + std::to_string(i + 1) + "]"));
    if (!p.entries.empty()) m.set("entries", std::move(entries));
    set_extras(m, "xml", p.extras);
    return m;
}

YNode ExportWriter::dc_time(const DcTime& t) {
    YNode m = YNode::map();
    m.set("value", YNode::integer(t.value));
    if (t.factor) m.set("factor", YNode::integer(*t.factor));
    if (t.input) m.set("input", YNode::boolean(*t.input));
    if (t.output_delay_time) m.set("output_delay_time", YNode::integer(*t.output_delay_time));
    if (t.input_delay_time) m.set("input_delay_time", YNode::integer(*t.input_delay_time));
    return m;
}

YNode ExportWriter::dc(const Dc& dc) {
    YNode m = YNode::map();
    YNode modes = YNode::seq();
    for (const auto& mode : dc.op_modes) {
        YNode x = YNode::map();
        x.set("name", YNode::text(mode.name));
        if (mode.desc) x.set("description", YNode::text(*mode.desc));
        if (mode.has_assign_activate) {
            if (mode.assign_activate > 0xFFFF) warn("Dc/OpMode[" + mode.name + "]/AssignActivate", "above 0xFFFF cannot be written");
            x.set("assign_activate", YNode::hex(mode.assign_activate, 4));
        }
        if (mode.cycle_time_sync0) x.set("cycle_time_sync0", dc_time(*mode.cycle_time_sync0));
        if (mode.shift_time_sync0) x.set("shift_time_sync0", dc_time(*mode.shift_time_sync0));
        if (mode.cycle_time_sync1) x.set("cycle_time_sync1", dc_time(*mode.cycle_time_sync1));
        if (mode.shift_time_sync1) x.set("shift_time_sync1", dc_time(*mode.shift_time_sync1));
        set_extras(x, "xml", mode.extras);
        modes.push(std::move(x));
    }
    m.set("op_modes", std::move(modes));
    if (dc.unknown_frmw) m.set("unknown_frmw", YNode::boolean(*dc.unknown_frmw));
    if (dc.unknown_64bit) m.set("unknown_64bit", YNode::boolean(*dc.unknown_64bit));
    if (dc.external_ref_clock) m.set("external_ref_clock", YNode::boolean(*dc.external_ref_clock));
    if (dc.potential_reference_clock) m.set("potential_reference_clock", YNode::boolean(*dc.potential_reference_clock));
    if (dc.time_loop_control_only) m.set("time_loop_control_only", YNode::boolean(*dc.time_loop_control_only));
    set_extras(m, "xml", dc.extras);
    return m;
}

YNode ExportWriter::slots(const Slots& s, const std::string& path) {
    YNode m = YNode::map();
    YNode list = YNode::seq();
    for (std::size_t i = 0; i < s.slots.size(); ++i) {
        const Slot& slot = s.slots[i];
        const std::string sp = path + "/Slots/Slot[" + std::to_string(i + 1) + "]";
        YNode x = YNode::map();
        names(x, "name", slot.names, sp);
        if (slot.module_idents.empty() == slot.module_classes.empty())
            warn(sp, "a slot with both (or neither) ModuleIdent and ModuleClass cannot be written exactly");
        if (!slot.module_idents.empty()) {
            YNode ms = YNode::seq();
            for (const auto& id : slot.module_idents) {
                if (!id.default_ident) {
                    ms.push(YNode::hex(id.value, 8));
                    continue;
                }
                YNode mm = YNode::map();
                mm.set("module", YNode::hex(id.value, 8));
                mm.set("default", YNode::hex(*id.default_ident, 8));
                ms.push(std::move(mm));
            }
            x.set("modules", std::move(ms));
        }
        if (!slot.module_classes.empty()) {
            YNode cs = YNode::seq();
            for (const auto& c : slot.module_classes) {
                YNode cm = YNode::map();
                cm.set("class", YNode::text(c.class_name));
                if (c.vendor_id) cm.set("vendor_id", YNode::hex(*c.vendor_id, 8));
                names(cm, "name", c.names, sp);
                set_extras(cm, "xml", c.extras);
                cs.push(std::move(cm));
            }
            x.set("module_classes", std::move(cs));
        }
        if (slot.default_ident) x.set("default", YNode::hex(*slot.default_ident, 8));
        if (slot.fallback) x.set("fallback", YNode::hex(*slot.fallback, 8));
        if (slot.slot_group) x.set("slot_group", YNode::unsigned_integer(*slot.slot_group));
        x.set("min_instances", YNode::unsigned_integer(slot.min_instances));
        x.set("max_instances", YNode::unsigned_integer(slot.max_instances));
        if (slot.slot_pdo_increment) x.set("slot_pdo_increment", YNode::unsigned_integer(*slot.slot_pdo_increment));
        if (slot.slot_group_pdo_increment) x.set("slot_group_pdo_increment", YNode::unsigned_integer(*slot.slot_group_pdo_increment));
        if (slot.slot_index_increment) x.set("slot_index_increment", YNode::hex(*slot.slot_index_increment, 4));
        if (slot.slot_group_index_increment) x.set("slot_group_index_increment", YNode::hex(*slot.slot_group_index_increment, 4));
        images(x, slot.images);
        set_extras(x, "xml", slot.extras);
        list.push(std::move(x));
    }
    m.set("list", std::move(list));
    if (s.max_slot_count) m.set("max_slot_count", YNode::unsigned_integer(*s.max_slot_count));
    if (s.max_slot_group_count) m.set("max_slot_group_count", YNode::unsigned_integer(*s.max_slot_group_count));
    if (s.slot_pdo_increment) m.set("slot_pdo_increment", YNode::unsigned_integer(*s.slot_pdo_increment));
    if (s.slot_group_pdo_increment) m.set("slot_group_pdo_increment", YNode::unsigned_integer(*s.slot_group_pdo_increment));
    if (s.slot_index_increment) m.set("slot_index_increment", YNode::hex(*s.slot_index_increment, 4));
    if (s.slot_group_index_increment) m.set("slot_group_index_increment", YNode::hex(*s.slot_group_index_increment, 4));
    set_extras(m, "xml", s.extras);
    return m;
}

YNode ExportWriter::eeprom(const Eeprom& e, const std::string& path) {
    YNode m = YNode::map();
    auto hex_field = [&](const char* key, const std::optional<HexData>& h) {
        if (!h) return;
        if (valid_hex(*h)) m.set(key, hex_data(*h));
        else warn(path + "/Eeprom/" + key, "'" + h->text + "' is not hex bytes; dropped");
    };
    if (e.byte_size) {
        if (*e.byte_size < 128 || *e.byte_size > 0x7FFFFFFF) warn(path + "/Eeprom/ByteSize", "out of the range the format takes (128..)");
        m.set("size", YNode::unsigned_integer(*e.byte_size));
    }
    hex_field("config_data", e.config_data);
    if (e.boot_strap && e.boot_strap->byte_length() != 8) warn(path + "/Eeprom/BootStrap", "not 8 bytes");
    hex_field("boot_strap", e.boot_strap);
    hex_field("data", e.data);
    if (!e.categories.empty()) {
        YNode list = YNode::seq();
        for (const auto& c : e.categories) {
            YNode x = YNode::map();
            x.set("number", YNode::unsigned_integer(c.cat_no));
            if (c.data) {
                if (valid_hex(*c.data)) x.set("data", hex_data(*c.data));
                else warn(path + "/Eeprom/Category", "data is not hex bytes; dropped");
            }
            if (c.data_string) x.set("data_string", YNode::text(*c.data_string));
            if (c.data_uint) x.set("data_uint", YNode::unsigned_integer(*c.data_uint));
            if (c.data_udint) x.set("data_udint", YNode::unsigned_integer(*c.data_udint));
            if (c.preserve_online_data) x.set("preserve_online_data", YNode::boolean(*c.preserve_online_data));
            set_extras(x, "xml", c.extras);
            list.push(std::move(x));
        }
        m.set("categories", std::move(list));
    }
    if (e.assign_to_pdi) m.set("assign_to_pdi", YNode::boolean(*e.assign_to_pdi));
    set_extras(m, "xml", e.extras);
    return m;
}

YNode ExportWriter::device(const Device& d, const EtherCATInfo& info, const OmitPlan& plan) {
    std::string path = "Device[" + d.type.text + "]";
    if (d.type.product_code) path = "Device[" + hex_text(*d.type.product_code, 8) + ":" + hex_text(d.type.revision_no.value_or(0), 8) + "]";
    YNode m = YNode::map();
    m.set("type", YNode::text(d.type.text));
    if (!d.type.product_code) warn(path + "/Type@ProductCode", "missing; the YAML format requires it");
    if (!d.type.revision_no) warn(path + "/Type@RevisionNo", "missing; the YAML format requires it");
    m.set("product_code", YNode::hex(d.type.product_code.value_or(0), 8));
    m.set("revision", YNode::hex(d.type.revision_no.value_or(0), 8));
    if (d.type.serial_no) m.set("serial_no", YNode::hex(*d.type.serial_no, 8));
    if (d.type.tc_cfg_mode_safe_op) m.set("tc_cfg_mode_safe_op", YNode::boolean(*d.type.tc_cfg_mode_safe_op));
    set_extras(m, "type_xml", d.type.extras);
    names(m, "name", d.names, path, true);
    names(m, "comment", d.comments, path);
    names(m, "url", d.urls, path);
    if (d.group_type) m.set("group", YNode::text(*d.group_type));
    else m.set("group", YNode::raw("null"));  // no GroupType, as in the file
    m.set("physics", YNode::text(d.physics));
    if (d.invisible) m.set("invisible", YNode::boolean(*d.invisible));
    images(m, d.images);

    const Dictionary* dict = nullptr;
    if (!d.profiles.empty()) {
        for (std::size_t i = 1; i < d.profiles.size(); ++i)
            if (d.profiles[i].dictionary) warn(path + "/Profile[" + std::to_string(i + 1) + "]", "a Dictionary outside the first Profile is dropped");
        if (d.profiles.size() == 1) {
            const Profile& p = d.profiles.front();
            if (p.profile_no && !p.add_info && !p.channel && !p.dictionary_file && p.extras.empty())
                m.set("profile", YNode::integer(*p.profile_no));
            else
                m.set("profile", profile(p));
        } else {
            YNode list = YNode::seq();
            for (const auto& p : d.profiles) list.push(profile(p));
            m.set("profile", std::move(list));
        }
        if (d.profiles.front().dictionary) dict = &*d.profiles.front().dictionary;
    }
    if (dict) dictionary(m, *dict, path, plan, &d);

    if (d.eeprom) m.set("eeprom", eeprom(*d.eeprom, path));
    if (d.mailbox) {
        m.set("mailbox", mailbox(*d.mailbox, &d, plan, path + "/Mailbox"));
        if (d.mailbox->coe && !d.mailbox->coe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < d.mailbox->coe->init_cmds.size(); ++i)
                list.push(init_cmd(d.mailbox->coe->init_cmds[i], MailboxProtocol::coe, path + "/Mailbox/CoE/InitCmd[" + std::to_string(i + 1) + "]"));
            m.set("init", std::move(list));
        }
    }
    if (!plan.sms && !d.sms.empty()) {
        YNode list = YNode::seq();
        for (const auto& sm : d.sms) {
            YNode x = YNode::map();
            x.set("type", YNode::text(sm.type));
            if (sm.start_address) x.set("address", YNode::hex(*sm.start_address, 4));
            if (sm.control_byte) x.set("control_byte", YNode::hex(*sm.control_byte, 2));
            if (sm.default_size) x.set("size", YNode::unsigned_integer(*sm.default_size));
            if (sm.min_size) x.set("min_size", YNode::unsigned_integer(*sm.min_size));
            if (sm.max_size) x.set("max_size", YNode::unsigned_integer(*sm.max_size));
            if (sm.enable) x.set("enable", YNode::unsigned_integer(*sm.enable));
            if (sm.is_virtual) x.set("virtual", YNode::boolean(*sm.is_virtual));
            if (sm.watchdog) x.set("watchdog", YNode::boolean(*sm.watchdog));
            if (sm.op_only) x.set("op_only", YNode::boolean(*sm.op_only));
            if (sm.fixed_assignment) x.set("fixed_assignment", YNode::boolean(*sm.fixed_assignment));
            if (sm.one_byte_mode) x.set("one_byte_mode", YNode::boolean(*sm.one_byte_mode));
            set_extras(x, "xml", sm.extras);
            list.push(std::move(x));
        }
        m.set("sms", std::move(list));
    }
    if (!plan.fmmus && !d.fmmus.empty()) {
        YNode list = YNode::seq();
        for (const auto& f : d.fmmus) {
            if (!f.sm && !f.su && !f.op_only && f.extras.empty()) {
                list.push(YNode::text(f.type));
                continue;
            }
            YNode x = YNode::map();
            x.set("type", YNode::text(f.type));
            if (f.sm) x.set("sm", YNode::unsigned_integer(*f.sm));
            if (f.su) x.set("su", YNode::unsigned_integer(*f.su));
            if (f.op_only) x.set("op_only", YNode::boolean(*f.op_only));
            set_extras(x, "xml", f.extras);
            list.push(std::move(x));
        }
        m.set("fmmus", std::move(list));
    }
    if (!d.sus.empty()) {
        YNode list = YNode::seq();
        for (const auto& su : d.sus) {
            YNode x = YNode::map();
            x.set("text", YNode::text(su.text));
            if (su.separate_su) x.set("separate_su", YNode::boolean(*su.separate_su));
            if (su.separate_frame) x.set("separate_frame", YNode::boolean(*su.separate_frame));
            if (su.depend_on_input_state) x.set("depend_on_input_state", YNode::boolean(*su.depend_on_input_state));
            if (su.frame_repeat_support) x.set("frame_repeat_support", YNode::boolean(*su.frame_repeat_support));
            set_extras(x, "xml", su.extras);
            list.push(std::move(x));
        }
        m.set("sync_units", std::move(list));
    }
    for (const auto* pdos : {&d.rx_pdos, &d.tx_pdos}) {
        if (pdos->empty()) continue;
        YNode list = YNode::seq();
        for (const auto& p : *pdos) list.push(pdo(p, plan, path));
        m.set(pdos == &d.rx_pdos ? "rxpdo" : "txpdo", std::move(list));
    }
    if (d.dc) m.set("dc", dc(*d.dc));
    if (d.slots) m.set("slots", slots(*d.slots, path));
    if (!plan.any()) {
        m.set("derive", YNode::boolean(false));
    } else {
        DeriveOptions o = plan.derive_options();
        // A group is derived only for a GroupType no group declares; the file's groups are all written.
        o.groups = !d.group_type || info.find_group(*d.group_type) != nullptr;
        YNode x = YNode::map();
        auto off = [&](const char* key, bool on) {
            if (!on) x.set(key, YNode::boolean(false));
        };
        off("groups", o.groups);
        off("mailbox", o.mailbox);
        off("sync_managers", o.sync_managers);
        off("fmmus", o.fmmus);
        off("pdo_assignment", o.pdo_assignment);
        off("pdo_entries", o.pdo_entries);
        off("mapping_objects", o.mapping_objects);
        off("assignment_objects", o.assignment_objects);
        off("sm_types_object", o.sm_types_object);
        off("identity_object", o.identity_object);
        off("device_type_object", o.device_type_object);
        off("data_types", o.data_types);
        if (!x.empty()) m.set("derive", std::move(x));
    }
    set_extras(m, "xml", d.extras);
    return m;
}

YNode ExportWriter::module(const Module& mo) {
    const std::string path = "Modules/Module[" + hex_text(mo.module_ident, 8) + "]";
    YNode m = YNode::map();
    m.set("type", YNode::text(mo.type));
    m.set("ident", YNode::hex(mo.module_ident, 8));
    if (mo.module_class) m.set("class", YNode::text(*mo.module_class));
    if (mo.module_pdo_group) m.set("pdo_group", YNode::integer(*mo.module_pdo_group));
    set_extras(m, "type_xml", mo.type_extras);
    names(m, "name", mo.names, path, true);
    images(m, mo.images);
    const OmitPlan none;
    if (mo.profile) {
        m.set("profile", profile(*mo.profile));
        if (mo.profile->dictionary) dictionary(m, *mo.profile->dictionary, path, none, nullptr);
    }
    if (mo.mailbox) {
        m.set("mailbox", mailbox(*mo.mailbox, nullptr, none, path + "/Mailbox"));
        if (mo.mailbox->coe && !mo.mailbox->coe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mo.mailbox->coe->init_cmds.size(); ++i)
                list.push(init_cmd(mo.mailbox->coe->init_cmds[i], MailboxProtocol::coe, path + "/Mailbox/CoE/InitCmd[" + std::to_string(i + 1) + "]"));
            m.set("init", std::move(list));
        }
    }
    for (const auto* pdos : {&mo.rx_pdos, &mo.tx_pdos}) {
        if (pdos->empty()) continue;
        YNode list = YNode::seq();
        for (const auto& p : *pdos) list.push(pdo(p, none, path));
        m.set(pdos == &mo.rx_pdos ? "rxpdo" : "txpdo", std::move(list));
    }
    if (mo.dc_op_mode_name) m.set("dc_op_mode", YNode::text(*mo.dc_op_mode_name));
    m.set("derive", YNode::boolean(false));
    set_extras(m, "xml", mo.extras);
    return m;
}

}  // namespace esi::yaml
