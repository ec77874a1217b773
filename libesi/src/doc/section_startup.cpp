// The start-up sections of a page: DC op modes (how the device is synchronised) and the InitCmds a
// master sends on state transitions, grouped by transition in the order a start-up runs them.

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <string>

#include "doc/markup.hpp"
#include "doc/sections.hpp"
#include "esi/plural.hpp"

namespace esi::doc {

namespace {

// Cycle/shift time with its factor spelled out: the time is `value` ns plus `factor` times the
// reference (ETG.2000 DcOpModeType: the bus cycle for Sync0, the SYNC0 cycle for Sync1's cycle;
// a negative factor divides it), so "1 × the cycle", not "0 ns × 1".
std::string dc_time_text(const std::optional<DcTime>& t, std::string_view reference) {
    if (!t) return {};
    if (!t->factor || *t->factor == 0) return std::to_string(t->value) + " ns";
    const std::int64_t factor = *t->factor;
    std::string out = factor > 0 ? std::to_string(factor) + " × " + std::string(reference)
                                 : std::string(reference) + " / " + std::to_string(-factor);
    if (t->value > 0) out += " + " + std::to_string(t->value) + " ns";
    else if (t->value < 0) out += " − " + std::to_string(-t->value) + " ns";
    return out;
}

struct TransitionName {
    std::string_view code;
    std::string_view words;
};
// ETG.1000.6 EtherCAT state machine transitions, in start-up order, then the way back down.
constexpr std::array transitions{
    TransitionName{"IP", "Init → Pre-Op"},        TransitionName{"PS", "Pre-Op → Safe-Op"},
    TransitionName{"SO", "Safe-Op → Op"},         TransitionName{"OS", "Op → Safe-Op"},
    TransitionName{"OP", "Op → Pre-Op"},          TransitionName{"SP", "Safe-Op → Pre-Op"},
    TransitionName{"PI", "Pre-Op → Init"},        TransitionName{"SI", "Safe-Op → Init"},
    TransitionName{"OI", "Op → Init"},            TransitionName{"IB", "Init → Bootstrap"},
    TransitionName{"BI", "Bootstrap → Init"},
};

std::size_t transition_rank(std::string_view code) {
    for (std::size_t i = 0; i < transitions.size(); ++i)
        if (transitions[i].code == code) return i;
    return transitions.size();
}

// SoE IDN: bit 15 P (product) or S (standard), bits 12-14 the parameter set, bits 0-11 the data
// block number (IEC 61800-7-204): S-0-0015.
std::string idn_text(std::int64_t idn) {
    if (idn < 0 || idn > 0xFFFF) return std::to_string(idn);
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "%c-%d-%04d", (idn & 0x8000) ? 'P' : 'S', static_cast<int>((idn >> 12) & 7),
                  static_cast<int>(idn & 0xFFF));
    return buffer;
}

struct Command {
    std::string_view protocol;
    const InitCmd* cmd;
};

std::string target_text(const Command& c) {
    const InitCmd& cmd = *c.cmd;
    if (c.protocol == "CoE" && cmd.index)
        return index_text(*cmd.index, cmd.subindex.value_or(0)) + (cmd.complete_access.value_or(false) ? " (complete access)" : "");
    if (c.protocol == "SoE" && cmd.idn)
        return "IDN " + idn_text(*cmd.idn) + (cmd.channel ? ", channel " + std::to_string(*cmd.channel) : std::string());
    if (c.protocol == "EoE" && cmd.type) return "type " + std::to_string(*cmd.type);
    return {};
}

std::string data_text(const InitCmd& cmd) {
    if (!cmd.has_data) return {};
    std::string out;
    const std::string& t = cmd.data.text;
    for (std::size_t k = 0; k < t.size(); k += 2) {
        if (!out.empty()) out += ' ';
        out += t.substr(k, 2);
    }
    for (char& ch : out) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return out;
}

}  // namespace

ViewValue dc_section(const Device& device, const PageContext& context) {
    if (!device.dc) return ViewValue::null();
    ViewArena& arena = *context.arena;
    ListBuilder modes(arena);
    for (const DcOpMode& m : device.dc->op_modes) {
        PageObject o(arena);
        o.add("name", m.name);
        o.add("description", m.desc.value_or(""));
        o.add("assign_activate_hex", m.has_assign_activate ? hex(m.assign_activate, 4) : std::string());
        o.add("cycle_sync0", dc_time_text(m.cycle_time_sync0, "the cycle"));
        o.add("shift_sync0", dc_time_text(m.shift_time_sync0, "the cycle"));
        o.add("cycle_sync1", dc_time_text(m.cycle_time_sync1, "the SYNC0 cycle"));
        o.add("shift_sync1", dc_time_text(m.shift_time_sync1, "the SYNC0 cycle"));
        modes.add(o.finish());
    }
    PageObject section(arena);
    section.add("op_mode_count", device.dc->op_modes.size());
    section.add("op_modes", modes.finish());
    return section.finish();
}

ViewValue init_cmds_section(const Mailbox* mailbox, const PageContext& context) {
    if (!mailbox) return ViewValue::null();
    std::vector<Command> commands;
    const auto collect = [&](std::string_view protocol, const std::vector<InitCmd>& list) {
        for (const InitCmd& c : list) commands.push_back({protocol, &c});
    };
    if (mailbox->coe) collect("CoE", mailbox->coe->init_cmds);
    if (mailbox->soe) collect("SoE", mailbox->soe->init_cmds);
    if (mailbox->eoe) collect("EoE", mailbox->eoe->init_cmds);
    if (mailbox->aoe) collect("AoE", mailbox->aoe->init_cmds);
    if (commands.empty()) return ViewValue::null();

    // Every transition any command names: the known ones in start-up order, then others as written.
    std::vector<std::string> names;
    for (const Command& c : commands)
        for (const Transition& t : c.cmd->transitions)
            if (std::find(names.begin(), names.end(), t.text) == names.end()) names.push_back(t.text);
    std::stable_sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
        const std::size_t ra = transition_rank(a), rb = transition_rank(b);
        return ra != rb ? ra < rb : (ra == transitions.size() && a < b);
    });

    ViewArena& arena = *context.arena;
    ListBuilder groups(arena);
    for (const std::string& name : names) {
        ListBuilder rows(arena);
        for (const Command& c : commands) {
            const auto& ts = c.cmd->transitions;
            if (std::none_of(ts.begin(), ts.end(), [&](const Transition& t) { return t.text == name; })) continue;
            PageObject o(arena);
            o.add("protocol", ViewValue::of_static(c.protocol));
            o.add("target", target_text(c));
            o.add("data", data_text(*c.cmd));
            o.add("comment", c.cmd->comment.value_or(""));
            rows.add(o.finish());
        }
        const std::size_t rank = transition_rank(name);
        PageObject g(arena);
        g.add("transition", name);
        g.add("words", rank < transitions.size() ? std::string(transitions[rank].words) : name);
        g.add("commands", rows.finish());
        groups.add(g.finish());
    }
    PageObject section(arena);
    section.add("command_count", commands.size());
    section.add("command_count_text", counted(commands.size(), "command"));
    section.add("transitions", groups.finish());
    return section.finish();
}

}  // namespace esi::doc
