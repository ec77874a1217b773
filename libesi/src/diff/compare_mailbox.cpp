// Mailbox: protocols, their capability flags and the InitCmds a master sends on state
// transitions. Capability flags are xs:boolean attributes whose absence means false; a flag that
// goes away is a capability a master may rely on (SII General category, ETG.2010). InitCmds are
// sent in the order written, so they are aligned like PDO entries: by what they address (CoE
// index:subindex, SoE IDN, EoE type), and what is not in the common subsequence moved, changed,
// was added or removed.

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "diff/compare.hpp"
#include "esi/model/mailbox_flags.hpp"
#include "diff/sequence.hpp"

namespace esi::diff_detail {

namespace {

std::string init_cmd_key(const InitCmd& c, MailboxProtocol protocol) {
    switch (protocol) {
        case MailboxProtocol::coe: return entry_key(c.index.value_or(0), c.subindex.value_or(0));
        case MailboxProtocol::soe:
            return c.channel ? fmt::format("IDN {} Chn {}", c.idn.value_or(0), *c.channel)
                             : fmt::format("IDN {}", c.idn.value_or(0));
        case MailboxProtocol::eoe: return fmt::format("Type {}", c.type.value_or(0));
        case MailboxProtocol::aoe: return "AoE";
        case MailboxProtocol::foe:
        case MailboxProtocol::voe: break;  // no InitCmds
    }
    return {};
}

std::string transitions(const InitCmd& c) {
    std::vector<std::string> t;
    for (const auto& x : c.transitions) t.push_back(std::string(trim(x.text)));
    std::sort(t.begin(), t.end());
    std::string out;
    for (const auto& s : t) out += (out.empty() ? "" : " ") + s;
    return out;
}

std::string describe_init_cmd(const InitCmd& c, MailboxProtocol protocol) {
    std::string out = protocol == MailboxProtocol::aoe ? std::string("AoE command") : init_cmd_key(c, protocol);
    out += fmt::format(" [{}]", transitions(c));
    if (c.has_data) out += " data " + (c.data.text.empty() ? std::string("(empty)") : normalized_hex(c.data));
    return out;
}

void compare_init_cmd(Recorder& r, const std::string& p, const InitCmd& a, const InitCmd& b) {
    r.value(ChangeKind::init_cmd_changed, child(p, "Transition"), "transitions", transitions(a), transitions(b), a.pos, b.pos);
    const auto data = [](const InitCmd& c) -> std::optional<std::string> {
        if (!c.has_data) return std::nullopt;
        return normalized_hex(c.data);
    };
    r.value(ChangeKind::init_cmd_changed, child(p, "Data"), "Data", data(a), data(b), a.data.pos.known() ? a.data.pos : a.pos,
            b.data.pos.known() ? b.data.pos : b.pos);
    const auto attribute = [&](std::string_view name, std::optional<std::string> x, std::optional<std::string> y) {
        r.value(ChangeKind::init_cmd_changed, attr(p, name), name, x, y, a.pos, b.pos);
    };
    attribute("Data@AdaptAutomatically", flag(a.data_adapt_automatically), flag(b.data_adapt_automatically));
    attribute("Fixed", flag(a.fixed), flag(b.fixed));
    attribute("CompleteAccess", flag(a.complete_access), flag(b.complete_access));
    attribute("OverwrittenByModule", flag(a.overwritten_by_module), flag(b.overwritten_by_module));
    attribute("Index@DependOnSlot", flag(a.index_depend_on_slot), flag(b.index_depend_on_slot));
    attribute("Index@DependOnSlotGroup", flag(a.index_depend_on_slot_group), flag(b.index_depend_on_slot_group));
    r.value(ChangeKind::comment_changed, child(p, "Comment"), "Comment", a.comment, b.comment, a.pos, b.pos);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

void compare_init_cmds(Recorder& r, const std::string& path, MailboxProtocol protocol, const std::vector<InitCmd>& a,
                       const std::vector<InitCmd>& b, SourcePos old_parent, SourcePos new_parent) {
    std::vector<std::string> ka;
    std::vector<std::string> kb;
    for (const auto& c : a) ka.push_back(init_cmd_key(c, protocol));
    for (const auto& c : b) kb.push_back(init_cmd_key(c, protocol));
    const Alignment alignment = align(
        ka, kb, [&](const std::string&) { return protocol != MailboxProtocol::aoe; }, true);

    // "InitCmd[#x1C12:00]", the second command with that key "InitCmd[#x1C12:00#2]"; AoE by position.
    auto path_of = [&](const std::vector<std::string>& keys, std::size_t i) -> std::string {
        if (protocol == MailboxProtocol::aoe) return child(path, indexed("InitCmd", std::to_string(i + 1)));
        const std::size_t occurrence =
            static_cast<std::size_t>(std::count(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(i), keys[i]));
        return child(path, indexed("InitCmd", occurrence ? fmt::format("{}#{}", keys[i], occurrence + 1) : keys[i]));
    };

    std::vector<Alignment::Pair> pairs = alignment.pairs;
    std::sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.new_index < y.new_index; });
    for (const auto& pair : pairs) {
        const InitCmd& x = a[pair.old_index];
        const InitCmd& y = b[pair.new_index];
        const std::string p = path_of(ka, pair.old_index);
        if (pair.how == Alignment::Pair::How::moved)
            r.add(ChangeKind::init_cmd_order_changed, p, fmt::format("position {}", pair.old_index + 1),
                  fmt::format("position {}", pair.new_index + 1), x.pos, y.pos,
                  fmt::format("InitCmd {} moved from position {} to {}", describe_init_cmd(y, protocol), pair.old_index + 1,
                              pair.new_index + 1));
        else if (pair.how == Alignment::Pair::How::replaced)
            r.add(ChangeKind::init_cmd_changed, p, describe_init_cmd(x, protocol), describe_init_cmd(y, protocol), x.pos, y.pos,
                  fmt::format("InitCmd {} now addresses {} instead of {}", pair.new_index + 1, kb[pair.new_index],
                              ka[pair.old_index]));
        compare_init_cmd(r, pair.how == Alignment::Pair::How::replaced ? path_of(kb, pair.new_index) : p, x, y);
    }
    for (std::size_t j : alignment.added)
        r.add(ChangeKind::init_cmd_added, path_of(kb, j), std::nullopt, describe_init_cmd(b[j], protocol), old_parent, b[j].pos,
              fmt::format("InitCmd {} added", describe_init_cmd(b[j], protocol)));
    for (std::size_t i : alignment.removed)
        r.add(ChangeKind::init_cmd_removed, path_of(ka, i), describe_init_cmd(a[i], protocol), std::nullopt, a[i].pos, new_parent,
              fmt::format("InitCmd {} removed", describe_init_cmd(a[i], protocol)));
}

// A capability flag: going from true to false is a lost capability.
void capability(Recorder& r, const std::string& path, std::string_view name, const std::optional<bool>& a,
                const std::optional<bool>& b, SourcePos pa, SourcePos pb) {
    const bool x = a.value_or(false);
    const bool y = b.value_or(false);
    if (x == y) return;
    r.value(y ? ChangeKind::mailbox_flag_set : ChangeKind::mailbox_flag_cleared, attr(path, name), name, flag(a), flag(b), pa,
            pb);
}

template <class Protocol, std::size_t N>
void capabilities(Recorder& r, const std::string& path, const Protocol& a, const Protocol& b,
                  const MailboxFlag<Protocol> (&flags)[N]) {
    for (const auto& flag : flags) capability(r, path, flag.attribute, a.*flag.field, b.*flag.field, a.pos, b.pos);
}

// Presence of a protocol element; returns whether both are present (and their contents should be compared).
template <class P>
bool presence(Recorder& r, const std::string& p, std::string_view name, const std::optional<P>& a, const std::optional<P>& b,
              SourcePos pa, SourcePos pb) {
    if (a && b) return true;
    if (a)
        r.add(ChangeKind::mailbox_protocol_removed, p, std::string(name), std::nullopt, a->pos, pb,
              fmt::format("mailbox protocol {} removed", name));
    if (b)
        r.add(ChangeKind::mailbox_protocol_added, p, std::nullopt, std::string(name), pa, b->pos,
              fmt::format("mailbox protocol {} added", name));
    return false;
}

}  // namespace

void compare_mailboxes(Recorder& r, const std::string& path, const std::optional<Mailbox>& a, const std::optional<Mailbox>& b,
                       SourcePos old_parent, SourcePos new_parent) {
    if (!a && !b) return;
    if (!a || !b) {
        const Mailbox& m = a ? *a : *b;
        const std::string protocols = mailbox_protocol_names(m.protocol_bits(), "(no protocol)");
        r.add(a ? ChangeKind::mailbox_removed : ChangeKind::mailbox_added, path,
              a ? std::optional<std::string>(protocols) : std::nullopt, b ? std::optional<std::string>(protocols) : std::nullopt,
              a ? a->pos : old_parent, b ? b->pos : new_parent,
              fmt::format("mailbox ({}) {}", protocols, a ? "removed" : "added"));
        // A mailbox that appears brings its InitCmds; a master configured without a mailbox never sent them.
        static const Mailbox empty;
        const Mailbox& x = a ? *a : empty;
        const Mailbox& y = b ? *b : empty;
        if (x.coe || y.coe)
            compare_init_cmds(r, child(path, "CoE"), MailboxProtocol::coe, x.coe ? x.coe->init_cmds : std::vector<InitCmd>{},
                              y.coe ? y.coe->init_cmds : std::vector<InitCmd>{}, old_parent, new_parent);
        return;
    }
    const Mailbox& x = *a;
    const Mailbox& y = *b;
    capability(r, path, "DataLinkLayer", x.data_link_layer, y.data_link_layer, x.pos, y.pos);
    capability(r, path, "RealTimeMode", x.real_time_mode, y.real_time_mode, x.pos, y.pos);

    const std::string coe = child(path, "CoE");
    if (presence(r, coe, "CoE", x.coe, y.coe, x.pos, y.pos)) {
        const CoeProtocol& c = *x.coe;
        const CoeProtocol& d = *y.coe;
        for (const auto& f : coe_flags) {
            // PdoUpload (SII General CoE details bit 4, "upload at startup") asks the master to read the
            // PDO configuration at start-up: an instruction, not a capability a configuration relies on.
            if (f.field == &CoeProtocol::pdo_upload)
                r.value(ChangeKind::mailbox_attribute_changed, attr(coe, f.attribute), f.attribute, flag(c.*f.field),
                        flag(d.*f.field), c.pos, d.pos);
            else
                capability(r, coe, f.attribute, c.*f.field, d.*f.field, c.pos, d.pos);
        }
        r.value(ChangeKind::mailbox_channels_changed, attr(coe, "DS402Channels"), "DS402Channels", dec(c.ds402_channels),
                dec(d.ds402_channels), c.pos, d.pos);
        r.value(ChangeKind::mailbox_attribute_changed, attr(coe, "EdsFile"), "EdsFile", c.eds_file, d.eds_file, c.pos, d.pos);
        compare_init_cmds(r, coe, MailboxProtocol::coe, c.init_cmds, d.init_cmds, c.pos, d.pos);
        compare_extras(r, coe, c.extras, d.extras, c.pos, d.pos);
    } else if (x.coe || y.coe) {
        compare_init_cmds(r, coe, MailboxProtocol::coe, x.coe ? x.coe->init_cmds : std::vector<InitCmd>{},
                          y.coe ? y.coe->init_cmds : std::vector<InitCmd>{}, x.coe ? x.coe->pos : x.pos,
                          y.coe ? y.coe->pos : y.pos);
    }

    const std::string eoe = child(path, "EoE");
    if (presence(r, eoe, "EoE", x.eoe, y.eoe, x.pos, y.pos)) {
        const EoeProtocol& c = *x.eoe;
        const EoeProtocol& d = *y.eoe;
        capabilities(r, eoe, c, d, eoe_flags);
        compare_init_cmds(r, eoe, MailboxProtocol::eoe, c.init_cmds, d.init_cmds, c.pos, d.pos);
        compare_extras(r, eoe, c.extras, d.extras, c.pos, d.pos);
    }

    const std::string soe = child(path, "SoE");
    if (presence(r, soe, "SoE", x.soe, y.soe, x.pos, y.pos)) {
        const SoeProtocol& c = *x.soe;
        const SoeProtocol& d = *y.soe;
        r.value(ChangeKind::mailbox_channels_changed, attr(soe, "ChannelCount"), "ChannelCount", dec(c.channel_count),
                dec(d.channel_count), c.pos, d.pos);
        capabilities(r, soe, c, d, soe_flags);
        compare_init_cmds(r, soe, MailboxProtocol::soe, c.init_cmds, d.init_cmds, c.pos, d.pos);
        compare_extras(r, soe, c.extras, d.extras, c.pos, d.pos);
    }

    const std::string aoe = child(path, "AoE");
    if (presence(r, aoe, "AoE", x.aoe, y.aoe, x.pos, y.pos)) {
        const AoeProtocol& c = *x.aoe;
        const AoeProtocol& d = *y.aoe;
        capabilities(r, aoe, c, d, aoe_flags);
        compare_init_cmds(r, aoe, MailboxProtocol::aoe, c.init_cmds, d.init_cmds, c.pos, d.pos);
        compare_extras(r, aoe, c.extras, d.extras, c.pos, d.pos);
    }

    const std::string foe = child(path, "FoE");
    if (presence(r, foe, "FoE", x.foe, y.foe, x.pos, y.pos))
        compare_extras(r, foe, x.foe->extras, y.foe->extras, x.foe->pos, y.foe->pos);
    const std::string voe = child(path, "VoE");
    if (presence(r, voe, "VoE", x.voe, y.voe, x.pos, y.pos))
        compare_extras(r, voe, x.voe->extras, y.voe->extras, x.voe->pos, y.voe->pos);

    compare_extras(r, path, x.extras, y.extras, x.pos, y.pos);
}

}  // namespace esi::diff_detail
