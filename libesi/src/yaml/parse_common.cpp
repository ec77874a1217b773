// Pieces shared by devices and modules: images, the XML escape hatch, object references,
// InitCmds and mailbox protocols. PDOs and their entries are in parse_pdos.cpp.

#include <algorithm>
#include <array>
#include <set>

#include "esi/derive/object_builder.hpp"
#include "esi/ethercat/al_state.hpp"
#include "esi/model/mailbox_flags.hpp"
#include "esi/text_distance.hpp"
#include "yaml/extras.hpp"
#include "yaml/source_parser.hpp"

namespace esi::yaml {

namespace {

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

std::string hex4(std::uint32_t v) {
    std::string s = format_hex(v, 4);
    return "0x" + s.substr(2);
}

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
    const std::span<const std::string_view> known = ethercat::state_machine_transition_names();
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
        if (std::find(known.begin(), known.end(), *t) == known.end()) {
            std::string list;
            for (const std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
            std::string message = "'" + *t + "' is not a state transition (" + list + ")";
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

}  // namespace esi::yaml
