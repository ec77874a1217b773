// Pieces shared by devices and modules: names per language, images, the XML escape hatch,
// profiles, PDOs and their entries; and the file-level vendor and groups. Every key written by the
// import_*.cpp files is one docs/yaml-format.md documents and the parser reads back into the same
// model field. Values the format cannot hold exactly are reported as warnings with their model path
// (the round-trip test lists them).

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

#include "esi/model/language.hpp"
#include "import/import_writer.hpp"

namespace esi::import_detail {

namespace {

// The language codes the YAML reader knows (esi/model/language.hpp); any other LcId is written as
// a number.
std::string language_key(std::uint32_t lcid) {
    if (const auto code = language_code(lcid)) return std::string(*code);
    return std::to_string(lcid);
}

std::string xml_escape(std::string_view s, bool attribute) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"':
                if (attribute) out += "&quot;";
                else out += c;
                break;
            case '\n':
                if (attribute) out += "&#10;";
                else out += c;
                break;
            case '\r': out += "&#13;"; break;
            case '\t':
                if (attribute) out += "&#9;";
                else out += c;
                break;
            default: out += c;
        }
    }
    return out;
}

// An unmodelled element back to XML text; character data first, then the children (the model
// keeps the element's text as one string).
void xml_text(const XmlElement& e, std::string& out) {
    out += "<" + e.name;
    for (const auto& a : e.attributes) out += " " + a.name + "=\"" + xml_escape(a.value, true) + "\"";
    if (e.text.empty() && e.children.empty()) {
        out += "/>";
        return;
    }
    out += ">";
    out += xml_escape(e.text, false);
    for (const auto& c : e.children) xml_text(c, out);
    out += "</" + e.name + ">";
}

}  // namespace

std::string hex_text(std::uint64_t v, int digits) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "0x%0*llX", digits, static_cast<unsigned long long>(v));
    return buffer;
}

YNode hex_data(const HexData& h) { return YNode::text(h.text); }

bool valid_hex(const HexData& h) {
    if (h.text.size() % 2 != 0) return false;
    return std::all_of(h.text.begin(), h.text.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
}

std::string child(const std::string& path, const std::string& name) { return path.empty() ? name : path + "/" + name; }

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

void ImportWriter::warn(const std::string& path, const std::string& message) {
    if (quiet) return;
    warnings_.emplace(Severity::warning, "import-inexact", path + ": " + message, "", SourcePos{});
}

void ImportWriter::names(YNode& map, std::string_view key, const Names& ns, const std::string& path, bool required) {
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
        const std::uint32_t lcid = n.lcid.value_or(1033);
        if (!seen.insert(lcid).second) {
            warn(child(path, std::string(key)), "LcId " + std::to_string(lcid) + " twice; the second is dropped");
            continue;
        }
        m.set_raw_key(quote_text(language_key(lcid)), YNode::text(n.text));
    }
    map.set(key, std::move(m));
}

void ImportWriter::images(YNode& map, const Images& images) {
    if (images.image_data16x14) map.set("image_data", hex_data(*images.image_data16x14));
    if (images.image_file16x14) map.set("image_file", YNode::text(*images.image_file16x14));
    if (images.image16x14) map.set("image16x14", YNode::text(*images.image16x14));
}

YNode ImportWriter::extras(const Extras& e) {
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

void ImportWriter::set_extras(YNode& map, std::string_view key, const Extras& e) {
    if (!e.empty()) map.set(key, extras(e));
}

YNode ImportWriter::vendor(const Vendor& v) {
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

YNode ImportWriter::group(const Group& g) {
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

YNode ImportWriter::profile(const Profile& p) {
    YNode m = YNode::map();
    if (p.profile_no) m.set("number", YNode::integer(*p.profile_no));
    if (p.add_info) m.set("add_info", YNode::integer(*p.add_info));
    if (p.channel) m.set("channel", YNode::integer(*p.channel));
    if (p.dictionary_file) m.set("dictionary_file", YNode::text(*p.dictionary_file));
    set_extras(m, "xml", p.extras);
    return m;
}

YNode ImportWriter::pdo_entry(const PdoEntry& e, const OmitPlan& plan, const std::string& path) {
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

YNode ImportWriter::pdo(const Pdo& p, const OmitPlan& plan, const std::string& path) {
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

}  // namespace esi::import_detail
