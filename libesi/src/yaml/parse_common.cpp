// Pieces shared by devices and modules: images, the XML escape hatch, object references,
// InitCmds, mailbox protocols, PDOs and their entries.

#include <algorithm>
#include <array>
#include <set>

#include "esi/derive/object_builder.hpp"
#include "esi/model/mailbox_flags.hpp"
#include "esi/text_distance.hpp"
#include "yaml/extras.hpp"
#include "yaml/source_parser.hpp"

namespace esi::yaml {

namespace {

std::string hex4(std::uint32_t v) {
    std::string s = format_hex(v, 4);
    return "0x" + s.substr(2);
}

// "0x6041:1", "0x1018:0x02", "24640:2": index and sub-index of an object.
std::optional<ObjectRef> split_ref(std::string_view text) {
    const auto colon = text.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    const ParsedNumber index = parse_number(text.substr(0, colon));
    const ParsedNumber sub = parse_number(text.substr(colon + 1));
    if (!index.ok() || !sub.ok() || index.value.negative || sub.value.negative) return std::nullopt;
    if (index.value.magnitude > 0xFFFF || sub.value.magnitude > 0xFF) return std::nullopt;
    return ObjectRef{static_cast<std::uint32_t>(index.value.magnitude), static_cast<std::uint32_t>(sub.value.magnitude)};
}

// "pad8", "pad 16": a padding entry of that many bits.
std::optional<std::uint32_t> padding_bits(std::string_view text) {
    if (text.size() < 4 || text.substr(0, 3) != "pad") return std::nullopt;
    const ParsedNumber n = parse_number(text.substr(3));
    if (!n.ok() || n.value.negative || n.value.magnitude == 0 || n.value.magnitude > 255) return std::nullopt;
    return static_cast<std::uint32_t>(n.value.magnitude);
}

// The keys an InitCmd of the protocol takes (format_keys.cpp).
Context init_cmd_context(MailboxProtocol protocol) {
    switch (protocol) {
        case MailboxProtocol::coe: return Context::init_coe;
        case MailboxProtocol::soe: return Context::init_soe;
        case MailboxProtocol::eoe: return Context::init_eoe;
        case MailboxProtocol::aoe:
        case MailboxProtocol::foe:  // FoE and VoE have no InitCmds: never asked
        case MailboxProtocol::voe: break;
    }
    return Context::init_aoe;
}

}  // namespace

ObjectNames index_object_names(const Dictionary& dictionary) {
    ObjectNames out;
    std::set<std::string_view> structured;
    for (const auto& t : dictionary.data_types)
        if (!t.sub_items.empty()) structured.insert(t.name);
    for (const auto& o : dictionary.objects) {
        const bool is_var = !structured.count(o.type);
        for (const auto& n : o.names) {
            if (n.text.empty()) continue;
            auto [it, inserted] = out.by_name.emplace(n.text, ObjectNames::Target{o.index, is_var, {}});
            if (!inserted && it->second.index != o.index) it->second.ambiguous_with.push_back(o.index);
        }
    }
    return out;
}

void SourceParser::images(const Fields& f, Images& out) {
    if (const Node* n = f.find("image_data")) out.image_data16x14 = r_.hex(*n, "image_data");
    if (const Node* n = f.find("image_file")) out.image_file16x14 = r_.text(*n, "image_file");
    if (const Node* n = f.find("image16x14")) {
        out.image16x14 = r_.text(*n, "image16x14");
        out.image16x14_pos = pos_of(*n);
    }
    const int given = (out.image_data16x14 ? 1 : 0) + (out.image_file16x14 ? 1 : 0) + (out.image16x14 ? 1 : 0);
    if (given > 1)
        r_.error(f.node(), "yaml-conflict", "give one of image_data, image_file and image16x14 (the ESI schema allows one image)");
}

void SourceParser::extras(const Fields& f, std::string_view key, Extras& out) {
    if (const Node* n = f.find(key)) read_extras(r_, *n, out, key);
}

Names SourceParser::names_of(const Fields& f, std::string_view key) {
    if (const Node* n = f.find(key)) return r_.names(*n, key);
    return {};
}

std::optional<ObjectRef> SourceParser::object_ref(const Node& node, const ObjectNames& names, std::string_view what) {
    if (!node.IsScalar()) {
        r_.error(node, "yaml-type", "'" + std::string(what) + "' must be an object index (0x6040), \"index:subindex\" or an object name");
        return std::nullopt;
    }
    const std::string text = node.Scalar();
    const ParsedNumber n = parse_number(text);
    if (n.ok()) {
        if (n.value.negative || n.value.magnitude > 0xFFFF) {
            r_.error(node, "yaml-number-range", "'" + std::string(what) + "' is " + format_decimal(n.value) + ", out of range 0..0xFFFF");
            return std::nullopt;
        }
        return ObjectRef{static_cast<std::uint32_t>(n.value.magnitude), std::nullopt};
    }
    if (auto ref = split_ref(text)) return ref;
    const auto it = names.by_name.find(text);
    if (it == names.by_name.end()) {
        std::vector<std::string_view> candidates;
        for (const auto& [name, target] : names.by_name) candidates.push_back(name);
        std::string message = "'" + std::string(what) + "': no object is named '" + text + "'";
        message += did_you_mean(text, candidates);
        r_.error(node, "yaml-reference", message);
        return std::nullopt;
    }
    if (!it->second.ambiguous_with.empty()) {
        std::string others;
        for (auto i : it->second.ambiguous_with) others += ", " + hex4(i);
        r_.error(node, "yaml-reference",
                 "'" + text + "' names several objects (" + hex4(it->second.index) + others + "); use the index");
        return std::nullopt;
    }
    ObjectRef ref{it->second.index, std::nullopt, !it->second.is_var};
    return ref;
}

std::optional<std::vector<Transition>> SourceParser::transitions(const Node& node) {
    // The EtherCAT state machine's transitions (ETG.1000.6 6.4.1; servo manuals Tabelle 8).
    static constexpr std::string_view known[] = {"IP", "PI", "PS", "SP", "SO", "OS", "OP", "SI", "OI", "IB", "BI"};
    std::vector<Node> items;
    if (node.IsSequence()) {
        for (const auto& n : node) items.push_back(n);
    } else {
        items.push_back(node);
    }
    std::vector<Transition> out;
    for (const auto& n : items) {
        const auto t = r_.text(n, "transition");
        if (!t) continue;
        if (std::find(std::begin(known), std::end(known), *t) == std::end(known)) {
            std::string message = "'" + *t + "' is not a state transition (IP, PS, SP, SO, OS, OP, PI, SI, OI, IB, BI)";
            message += did_you_mean(*t, known);
            r_.error(n, "yaml-value", message);
            continue;
        }
        out.push_back(Transition{*t, pos_of(n)});
    }
    if (out.empty() && items.empty()) {
        r_.error(node, "yaml-type", "'transition' needs at least one transition");
        return std::nullopt;
    }
    return out;
}

DeriveOptions SourceParser::derive_options(const Node& node, bool module) {
    DeriveOptions o;
    if (node.IsScalar()) {
        if (auto all = r_.boolean(node, "derive"); all && !*all) o = DeriveOptions::none();
        return o;
    }
    const auto f = r_.mapping(node, module ? Context::module_derive : Context::derive, "derive");
    if (!f) return o;
    auto set = [&](std::string_view key, bool& field) {
        if (const Node* n = f->find(key))
            if (auto b = r_.boolean(*n, key)) field = *b;
    };
    set("groups", o.groups);
    set("mailbox", o.mailbox);
    set("sync_managers", o.sync_managers);
    set("fmmus", o.fmmus);
    set("pdo_assignment", o.pdo_assignment);
    set("pdo_entries", o.pdo_entries);
    set("mapping_objects", o.mapping_objects);
    set("assignment_objects", o.assignment_objects);
    set("sm_types_object", o.sm_types_object);
    set("identity_object", o.identity_object);
    set("device_type_object", o.device_type_object);
    set("data_types", o.data_types);
    return o;
}

std::optional<Profile> SourceParser::profile(const Node& node) {
    Profile p;
    p.pos = pos_of(node);
    if (node.IsScalar()) {
        p.profile_no = r_.integer<std::int32_t>(node, "profile");
        return p;
    }
    const auto f = r_.mapping(node, Context::profile, "profile");
    if (!f) return std::nullopt;
    r_.optional_integer(*f, "number", p.profile_no);
    r_.optional_integer(*f, "add_info", p.add_info);
    r_.optional_integer(*f, "channel", p.channel);
    r_.optional_text(*f, "dictionary_file", p.dictionary_file);
    extras(*f, "xml", p.extras);
    return p;
}

void SourceParser::init_cmds(const Node& node, MailboxProtocol protocol, const ObjectNames& names, std::vector<InitCmd>& out,
                             std::vector<InitCmdValue>* values) {
    const auto items = r_.sequence(node, "init");
    if (!items) return;
    for (const auto& item : *items) {
        const auto f = r_.mapping(item, init_cmd_context(protocol), "an InitCmd");
        if (!f) continue;
        InitCmd cmd;
        cmd.pos = f->pos();
        if (r_.require(*f, "transition", "an InitCmd"))
            if (auto t = transitions(*f->find("transition"))) cmd.transitions = std::move(*t);
        std::optional<SourceValue> value;
        if (protocol == MailboxProtocol::coe) {
            std::optional<ObjectRef> ref;
            if (r_.require(*f, "object", "a CoE InitCmd")) ref = object_ref(*f->find("object"), names, "object");
            if (ref) {
                cmd.index = ref->index;
                cmd.subindex = ref->subindex;
            }
            if (const Node* n = f->find("subindex")) {
                const auto sub = r_.integer<std::uint32_t>(*n, "subindex", 0, 255);
                if (sub && ref && ref->subindex && *ref->subindex != *sub)
                    r_.error(*n, "yaml-conflict", "the sub-index is given twice ('object' and 'subindex') and differs");
                if (sub) cmd.subindex = sub;
            } else if (ref && ref->names_record && !ref->subindex) {
                r_.error(*f->find("object"), "yaml-reference", "this object is a record; give 'subindex'");
            }
            if (cmd.index && !cmd.subindex) cmd.subindex = 0;
            if (const Node* n = f->find("value")) value = r_.scalar_value(*n, "value");
            r_.optional_bool(*f, "complete_access", cmd.complete_access);
            r_.optional_bool(*f, "index_depend_on_slot", cmd.index_depend_on_slot);
            r_.optional_bool(*f, "index_depend_on_slot_group", cmd.index_depend_on_slot_group);
        }
        if (protocol == MailboxProtocol::soe) {
            if (const Node* n = f->find("idn")) cmd.idn = r_.integer<std::int64_t>(*n, "idn", 0, 0xFFFF);
            r_.optional_integer(*f, "channel", cmd.channel);
        }
        if (protocol == MailboxProtocol::eoe) {
            if (r_.require(*f, "type", "an EoE InitCmd")) cmd.type = r_.integer<std::int64_t>(*f->find("type"), "type", INT32_MIN, INT32_MAX);
        }
        if (const Node* n = f->find("data")) {
            if (auto h = r_.hex(*n, "data")) {
                cmd.data = *h;
                cmd.has_data = true;
            }
        }
        if (f->has("value") && f->has("data"))
            r_.error(*f->key_node("data"), "yaml-conflict", "give either 'value' (typed by the object) or 'data' (raw bytes), not both");
        else if (!f->has("value") && !f->has("data"))
            r_.error(f->node(), "yaml-missing-key", protocol == MailboxProtocol::coe ? "an InitCmd needs 'value' or 'data'" : "an InitCmd needs 'data'");
        if (const Node* n = f->find("adapt_automatically")) cmd.data_adapt_automatically = r_.boolean(*n, "adapt_automatically");
        r_.optional_text(*f, "comment", cmd.comment);
        r_.optional_bool(*f, "fixed", cmd.fixed);
        r_.optional_bool(*f, "overwritten_by_module", cmd.overwritten_by_module);
        extras(*f, "xml", cmd.extras);
        if (value && values) values->push_back(InitCmdValue{out.size(), *value});
        out.push_back(std::move(cmd));
    }
}

std::optional<Mailbox> SourceParser::mailbox(const Node& node, Context context, MailboxLayout* layout,
                                             const ObjectNames& names) {
    const auto f = r_.mapping(node, context, "mailbox");
    if (!f) return std::nullopt;
    Mailbox m;
    m.pos = f->pos();
    if (layout) {
        layout->pos = m.pos;
        if (const Node* n = f->find("size")) {
            layout->out_size = layout->in_size = r_.integer<std::uint32_t>(*n, "size", 8, 0xFFFF);
            layout->pos = pos_of(*n);
            for (const char* k : {"out_size", "in_size"})
                if (f->has(k)) r_.error(*f->key_node(k), "yaml-conflict", "give either 'size' (both directions) or 'out_size'/'in_size'");
        }
        if (const Node* n = f->find("out_size")) layout->out_size = r_.integer<std::uint32_t>(*n, "out_size", 8, 0xFFFF);
        if (const Node* n = f->find("in_size")) layout->in_size = r_.integer<std::uint32_t>(*n, "in_size", 8, 0xFFFF);
        if (const Node* n = f->find("out_address")) layout->out_address = r_.integer<std::uint32_t>(*n, "out_address", 0, 0xFFFF);
        if (const Node* n = f->find("in_address")) layout->in_address = r_.integer<std::uint32_t>(*n, "in_address", 0, 0xFFFF);
    }
    r_.optional_bool(*f, "data_link_layer", m.data_link_layer);
    r_.optional_bool(*f, "real_time_mode", m.real_time_mode);
    extras(*f, "xml", m.extras);

    // A protocol is `true`, `false` or a mapping of its settings.
    auto protocol = [&](std::string_view key, Context ctx) -> std::optional<Fields> {
        const Node* n = f->find(key);
        if (!n) return std::nullopt;
        if (n->IsScalar()) {
            if (auto on = r_.boolean(*n, key); on && *on) return Fields(Node::empty_map());
            return std::nullopt;
        }
        return r_.mapping(*n, ctx, key);
    };
    auto read_flags = [&](const Fields& p, auto& out, const auto& flags) {
        for (const auto& flag : flags) r_.optional_bool(p, flag.key, out.*flag.field);
    };
    // EoE, SoE and AoE: after their typed settings, their InitCmds and unmodelled XML.
    auto init_cmds_and_xml = [&](const Fields& p, auto& out, MailboxProtocol which) {
        if (const Node* n = p.find("init")) init_cmds(*n, which, names, out.init_cmds, nullptr);
        extras(p, "xml", out.extras);
    };
    if (auto p = protocol("coe", Context::coe)) {
        CoeProtocol coe;
        coe.pos = f->find("coe") ? pos_of(*f->find("coe")) : m.pos;
        read_flags(*p, coe, coe_flags);
        r_.optional_text(*p, "eds_file", coe.eds_file);
        r_.optional_integer(*p, "ds402_channels", coe.ds402_channels);
        extras(*p, "xml", coe.extras);
        m.coe = std::move(coe);
    }
    if (auto p = protocol("eoe", Context::eoe)) {
        EoeProtocol eoe;
        eoe.pos = pos_of(*f->find("eoe"));
        read_flags(*p, eoe, eoe_flags);
        init_cmds_and_xml(*p, eoe, MailboxProtocol::eoe);
        m.eoe = std::move(eoe);
    }
    if (auto p = protocol("soe", Context::soe)) {
        SoeProtocol soe;
        soe.pos = pos_of(*f->find("soe"));
        r_.optional_integer(*p, "channel_count", soe.channel_count);
        read_flags(*p, soe, soe_flags);
        init_cmds_and_xml(*p, soe, MailboxProtocol::soe);
        m.soe = std::move(soe);
    }
    if (auto p = protocol("aoe", Context::aoe)) {
        AoeProtocol aoe;
        aoe.pos = pos_of(*f->find("aoe"));
        read_flags(*p, aoe, aoe_flags);
        init_cmds_and_xml(*p, aoe, MailboxProtocol::aoe);
        m.aoe = std::move(aoe);
    }
    for (const char* key : {"foe", "voe"}) {
        if (auto p = protocol(key, Context::plain_protocol)) {
            PlainProtocol plain;
            plain.pos = pos_of(*f->find(key));
            extras(*p, "xml", plain.extras);
            (std::string_view(key) == "foe" ? m.foe : m.voe) = std::move(plain);
        }
    }
    return m;
}

std::optional<PdoEntry> SourceParser::pdo_entry(const Node& node, const ObjectNames& names) {
    PdoEntry e;
    e.pos = pos_of(node);
    if (node.IsScalar()) {
        if (auto bits = padding_bits(node.Scalar())) {
            e.index = 0;
            e.bit_len = *bits;
            e.bit_len_pos = e.pos;
            return e;
        }
        auto ref = object_ref(node, names, "entry");
        if (!ref) return std::nullopt;
        if (ref->names_record) {
            r_.error(node, "yaml-reference",
                     "'" + node.Scalar() + "' is a record; name the entry as \"index:subindex\" or {object: …, subindex: …}");
            return std::nullopt;
        }
        e.index = ref->index;
        e.index_pos = e.pos;
        e.subindex = ref->subindex;
        if (e.index == 0) {
            r_.error(node, "yaml-value", "index 0 is padding; write padding as pad8, pad16 … or {pad: bits}");
            return std::nullopt;
        }
        return e;
    }
    const auto f = r_.mapping(node, Context::pdo_entry, "a PDO entry");
    if (!f) return std::nullopt;
    if (f->has("object") == f->has("pad")) {
        r_.error(f->node(), "yaml-missing-key", "a PDO entry needs either 'object' or 'pad'");
        return std::nullopt;
    }
    if (const Node* n = f->find("pad")) {
        e.index = 0;
        e.bit_len = r_.integer<std::uint32_t>(*n, "pad", 1, 255).value_or(0);
        e.bit_len_pos = pos_of(*n);
        if (f->has("bit_len")) r_.error(*f->key_node("bit_len"), "yaml-conflict", "'pad' is the padding's bit length; drop 'bit_len'");
        // Written files often spell padding <Index>0</Index><SubIndex>0</SubIndex>; keep that.
        r_.optional_integer<std::uint32_t>(*f, "subindex", e.subindex, 0, 255);
    } else {
        auto ref = object_ref(*f->find("object"), names, "object");
        if (!ref) return std::nullopt;
        e.index = ref->index;
        e.index_pos = pos_of(*f->find("object"));
        e.subindex = ref->subindex;
        if (const Node* n = f->find("subindex")) {
            const auto sub = r_.integer<std::uint32_t>(*n, "subindex", 0, 255);
            if (sub && ref->subindex && *ref->subindex != *sub)
                r_.error(*n, "yaml-conflict", "the sub-index is given twice ('object' and 'subindex') and differs");
            if (sub) e.subindex = sub;
        } else if (ref->names_record && !ref->subindex) {
            r_.error(*f->find("object"), "yaml-reference", "this object is a record; give 'subindex'");
            return std::nullopt;
        }
        if (e.index == 0) {
            r_.error(*f->find("object"), "yaml-value", "index 0 is padding; write {pad: bits}");
            return std::nullopt;
        }
        if (const Node* n = f->find("bit_len")) {
            e.bit_len = r_.integer<std::uint32_t>(*n, "bit_len", 1, 255).value_or(0);
            e.bit_len_pos = pos_of(*n);
        }
    }
    e.names = names_of(*f, "name");
    r_.optional_text(*f, "comment", e.comment);
    if (const Node* n = f->find("data_type")) {
        e.data_type = r_.text(*n, "data_type");
        e.data_type_pos = pos_of(*n);
    }
    r_.optional_text(*f, "dscale", e.data_type_dscale);
    if (const Node* n = f->find("swap_data")) {
        // ETG.2000: DataType@SwapData is one of Swap_HB_LB, Swap_HW_LW, Swap_HB_LB_HW_LW.
        static constexpr std::string_view swaps[] = {"Swap_HB_LB", "Swap_HW_LW", "Swap_HB_LB_HW_LW"};
        if (auto v = r_.text(*n, "swap_data")) {
            if (std::find(std::begin(swaps), std::end(swaps), *v) == std::end(swaps))
                r_.error(*n, "yaml-value",
                         "'swap_data' is Swap_HB_LB, Swap_HW_LW or Swap_HB_LB_HW_LW, not '" + *v + "'" + did_you_mean(*v, swaps));
            else
                e.data_type_swap_data = *v;
        }
    }
    r_.optional_bool(*f, "fixed", e.fixed);
    r_.optional_bool(*f, "index_depend_on_slot", e.index_depend_on_slot);
    r_.optional_bool(*f, "index_depend_on_slot_group", e.index_depend_on_slot_group);
    extras(*f, "xml", e.extras);
    return e;
}

std::vector<Pdo> SourceParser::pdos(const Node& node, PdoDirection direction, const ObjectNames& names, std::vector<bool>* assign) {
    std::vector<Pdo> out;
    const char* what = direction == PdoDirection::rx ? "rxpdo" : "txpdo";
    const auto items = r_.sequence(node, what);
    if (!items) return out;
    std::map<std::uint32_t, SourcePos> seen;
    for (const auto& item : *items) {
        const auto f = r_.mapping(item, Context::pdo, "a PDO");
        if (!f) continue;
        Pdo p;
        p.direction = direction;
        p.pos = f->pos();
        if (r_.require(*f, "index", "a PDO")) {
            p.index = r_.integer<std::uint32_t>(*f->find("index"), "index", 0, 0xFFFF).value_or(0);
            p.index_pos = pos_of(*f->find("index"));
            if (const auto [it, inserted] = seen.emplace(p.index, p.index_pos); !inserted) {
                Diagnostic& d = r_.error(p.index_pos, "yaml-duplicate", "PDO " + hex4(p.index) + " is declared twice");
                d.notes.push_back({r_.path(), it->second, "first declared here"});
            }
        }
        p.names = names_of(*f, "name");
        r_.optional_bool(*f, "fixed", p.fixed);
        r_.optional_bool(*f, "mandatory", p.mandatory);
        r_.optional_bool(*f, "virtual", p.is_virtual);
        r_.optional_integer<std::uint32_t>(*f, "sm", p.sm, 0, 31);
        bool assigned = true;
        if (const Node* n = f->find("assigned")) {
            assigned = r_.boolean(*n, "assigned").value_or(true);
            if (!assigned && f->has("sm")) r_.error(*n, "yaml-conflict", "'assigned: false' contradicts 'sm'");
        }
        if (assign) assign->push_back(assigned);
        r_.optional_integer<std::uint32_t>(*f, "su", p.su, 0, 255);
        if (const Node* n = f->find("exclude")) {
            if (auto list = r_.sequence(*n, "exclude")) {
                for (const auto& x : *list) {
                    PdoExclude ex;
                    ex.pos = pos_of(x);
                    if (x.IsMap()) {
                        const auto xf = r_.mapping(x, Context::pdo_exclude, "an exclude");
                        if (!xf || !r_.require(*xf, "index", "an exclude")) continue;
                        ex.index = r_.integer<std::uint32_t>(*xf->find("index"), "index", 0, 0xFFFF).value_or(0);
                        r_.optional_bool(*xf, "depend_on_slot", ex.depend_on_slot);
                        r_.optional_bool(*xf, "depend_on_slot_group", ex.depend_on_slot_group);
                    } else if (auto i = r_.integer<std::uint32_t>(x, "exclude", 0, 0xFFFF)) {
                        ex.index = *i;
                    } else {
                        continue;
                    }
                    p.excludes.push_back(ex);
                }
            }
        }
        if (const Node* n = f->find("excluded_sms")) {
            if (auto list = r_.sequence(*n, "excluded_sms"))
                for (const auto& x : *list)
                    if (auto v = r_.integer<std::uint32_t>(x, "excluded_sms", 0, 31)) p.excluded_sms.push_back(*v);
        }
        r_.optional_integer(*f, "pdo_order", p.pdo_order);
        r_.optional_integer(*f, "os_fac", p.os_fac);
        r_.optional_integer(*f, "os_min", p.os_min);
        r_.optional_integer(*f, "os_max", p.os_max);
        r_.optional_integer(*f, "os_index_inc", p.os_index_inc);
        r_.optional_bool(*f, "overwritten_by_module", p.overwritten_by_module);
        r_.optional_bool(*f, "sra_parameter", p.sra_parameter);
        r_.optional_text(*f, "safety_pdo_type", p.safety_pdo_type);
        r_.optional_integer(*f, "safety_conn_number", p.safety_conn_number);
        r_.optional_bool(*f, "index_depend_on_slot", p.index_depend_on_slot);
        r_.optional_bool(*f, "index_depend_on_slot_group", p.index_depend_on_slot_group);
        if (const Node* n = f->find("entries")) {
            if (auto list = r_.sequence(*n, "entries")) {
                if (list->size() > 254) r_.error(*n, "yaml-value", "a PDO maps at most 254 entries");
                for (const auto& x : *list)
                    if (auto e = pdo_entry(x, names)) p.entries.push_back(std::move(*e));
            }
        }
        extras(*f, "xml", p.extras);
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace esi::yaml
