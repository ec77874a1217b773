// ESI XML -> model: Mailbox (of a Device or a Module) with its protocols (CoE, EoE, SoE, AoE,
// FoE, VoE) and the InitCmds a master sends on state transitions.

#include "xml/reader_context.hpp"

namespace esi::xml_reader {

namespace {

// EoE and AoE have flags only.
constexpr auto no_other_attribute = [](const Attr&) { return false; };

}  // namespace

void Reader::read_init_cmd(InitCmd& cmd, const Element n) {
    cmd.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "Fixed")) cmd.fixed = boolean(a, n);
        else if (is(an, "CompleteAccess")) cmd.complete_access = boolean(a, n);
        else if (is(an, "OverwrittenByModule")) cmd.overwritten_by_module = boolean(a, n);
        else if (is(an, "Chn")) cmd.channel = i32(a, n);
        else keep(cmd.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Transition")) cmd.transitions.push_back(Transition{text_of(c), pos_of(c)});
        else if (is(name, "Index")) {
            cmd.index = u32(c);
            depend_on_slot(c, cmd.index_depend_on_slot, cmd.index_depend_on_slot_group);
        } else if (is(name, "SubIndex")) cmd.subindex = u32(c);
        else if (is(name, "IDN")) cmd.idn = i64(c);
        else if (is(name, "Type")) cmd.type = i64(c);
        else if (is(name, "Data")) {
            cmd.data = hex(c);
            cmd.has_data = true;
            for (const Attr& a : c.attributes())
                if (is(a.name, "AdaptAutomatically")) cmd.data_adapt_automatically = boolean(a, c);
        } else if (is(name, "Comment")) text(cmd.comment, c);
        else keep(cmd.extras, c, previous);
    });
}

// A protocol element with InitCmds (CoE, EoE, SoE, AoE): its flags, what `attribute` takes
// (true when it read the attribute), and its InitCmds; anything else is kept verbatim.
template <class Protocol, std::size_t N, class Attribute>
void Reader::read_protocol(Protocol& p, const Element n, const MailboxFlag<Protocol> (&flags)[N], Attribute&& attribute) {
    p.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        if (attribute(a)) continue;
        const std::string_view an = a.name;
        const auto flag = std::find_if(std::begin(flags), std::end(flags), [&](const auto& f) { return f.attribute == an; });
        if (flag != std::end(flags)) p.*(flag->field) = boolean(a, n);
        else keep(p.extras, a);
    }
    reserve_for(p.init_cmds, n, "InitCmd");
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "InitCmd")) read_init_cmd(p.init_cmds.emplace_back(), c);
        else keep(p.extras, c, previous);
    });
}

void Reader::read_mailbox(Mailbox& m, const Element n) {
    m.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "DataLinkLayer")) m.data_link_layer = boolean(a, n);
        else if (is(an, "RealTimeMode")) m.real_time_mode = boolean(a, n);
        else keep(m.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "CoE")) {
            CoeProtocol& coe = m.coe.emplace();
            read_protocol(coe, c, coe_flags, [&](const Attr& a) {
                const std::string_view an = a.name;
                if (is(an, "EdsFile")) coe.eds_file = a.value;
                else if (is(an, "DS402Channels")) coe.ds402_channels = i32(a, c);
                else return false;
                return true;
            });
        } else if (is(name, "EoE")) {
            read_protocol(m.eoe.emplace(), c, eoe_flags, no_other_attribute);
        } else if (is(name, "SoE")) {
            SoeProtocol& soe = m.soe.emplace();
            read_protocol(soe, c, soe_flags, [&](const Attr& a) {
                if (!is(a.name, "ChannelCount")) return false;
                soe.channel_count = i32(a, c);
                return true;
            });
        } else if (is(name, "AoE")) {
            read_protocol(m.aoe.emplace(), c, aoe_flags, no_other_attribute);
        } else if (is(name, "FoE") || is(name, "VoE")) {
            PlainProtocol p;
            p.pos = pos_of(c);
            for (const Attr& a : c.attributes()) keep(p.extras, a);
            for_children(c, [&](const Element cc, std::string_view, std::string_view prev) { keep(p.extras, cc, prev); });
            (is(name, "FoE") ? m.foe : m.voe) = std::move(p);
        } else {
            keep(m.extras, c, previous);
        }
    });
}

}  // namespace esi::xml_reader
