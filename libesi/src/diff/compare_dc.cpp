// Distributed clocks: operation modes pair up by Name (the key a configuration stores), their
// AssignActivate and default Sync0/Sync1 times are compared, and the Dc attributes that tell a
// master how to run the clock through the device.

#include <map>

#include <fmt/format.h>

#include "diff/compare.hpp"

namespace esi::diff_detail {

namespace {

std::optional<std::string> spell_time(const std::optional<DcTime>& t) {
    if (!t) return std::nullopt;
    std::string out = std::to_string(t->value);
    if (t->factor) out += fmt::format(" Factor={}", *t->factor);
    if (t->input) out += fmt::format(" Input={}", flag(t->input));
    if (t->output_delay_time) out += fmt::format(" OutputDelayTime={}", *t->output_delay_time);
    if (t->input_delay_time) out += fmt::format(" InputDelayTime={}", *t->input_delay_time);
    return out;
}

SourcePos pos_of(const std::optional<DcTime>& t, SourcePos fallback) { return t && t->pos.known() ? t->pos : fallback; }

void compare_op_mode(Recorder& r, const std::string& p, const DcOpMode& a, const DcOpMode& b) {
    r.value(ChangeKind::comment_changed, child(p, "Desc"), "Desc", a.desc, b.desc, a.pos, b.pos);
    const auto assign = [](const DcOpMode& m) -> std::optional<std::string> {
        if (!m.has_assign_activate) return std::nullopt;
        return hex(m.assign_activate);
    };
    r.value(
        ChangeKind::dc_assign_activate_changed, child(p, "AssignActivate"),
        [&] { return fmt::format("AssignActivate of DC mode {}", quote(b.name)); }, assign(a), assign(b),
        a.assign_activate_pos.known() ? a.assign_activate_pos : a.pos,
        b.assign_activate_pos.known() ? b.assign_activate_pos : b.pos);
    const auto time = [&](std::string_view name, const std::optional<DcTime>& x, const std::optional<DcTime>& y) {
        r.value(
            ChangeKind::dc_timing_changed, child(p, name), [&] { return fmt::format("{} of DC mode {}", name, quote(b.name)); },
            spell_time(x), spell_time(y), pos_of(x, a.pos), pos_of(y, b.pos));
    };
    time("CycleTimeSync0", a.cycle_time_sync0, b.cycle_time_sync0);
    time("ShiftTimeSync0", a.shift_time_sync0, b.shift_time_sync0);
    time("CycleTimeSync1", a.cycle_time_sync1, b.cycle_time_sync1);
    time("ShiftTimeSync1", a.shift_time_sync1, b.shift_time_sync1);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

}  // namespace

void compare_dc(Recorder& r, const std::string& path, const std::optional<Dc>& a, const std::optional<Dc>& b,
                SourcePos old_parent, SourcePos new_parent) {
    if (!a && !b) return;
    static const Dc none;
    const Dc& x = a ? *a : none;
    const Dc& y = b ? *b : none;
    const SourcePos px = a ? a->pos : old_parent;
    const SourcePos py = b ? b->pos : new_parent;

    std::map<std::string, std::vector<const DcOpMode*>> ma;
    std::map<std::string, std::vector<const DcOpMode*>> mb;
    std::vector<std::string> order;
    for (const auto& m : y.op_modes) {
        if (!mb.count(m.name)) order.push_back(m.name);
        mb[m.name].push_back(&m);
    }
    for (const auto& m : x.op_modes) {
        if (!ma.count(m.name) && !mb.count(m.name)) order.push_back(m.name);
        ma[m.name].push_back(&m);
    }
    for (const auto& name : order) {
        const auto& la = ma[name];
        const auto& lb = mb[name];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const DcOpMode* m = i < la.size() ? la[i] : nullptr;
            const DcOpMode* o = i < lb.size() ? lb[i] : nullptr;
            const std::string p = child(path, indexed("OpMode", n > 1 ? fmt::format("{}#{}", name, i + 1) : name));
            if (m && o) {
                compare_op_mode(r, p, *m, *o);
                continue;
            }
            const DcOpMode& e = m ? *m : *o;
            const std::string value =
                e.has_assign_activate ? fmt::format("AssignActivate {}", hex(e.assign_activate)) : std::string("-");
            const std::string desc = e.desc ? " " + quote(*e.desc) : std::string();
            r.add(m ? ChangeKind::dc_op_mode_removed : ChangeKind::dc_op_mode_added, p,
                  m ? std::optional<std::string>(value) : std::nullopt, o ? std::optional<std::string>(value) : std::nullopt,
                  m ? m->pos : px, o ? o->pos : py, fmt::format("DC mode {}{} {}", quote(name), desc, m ? "removed" : "added"));
        }
    }
    const auto attribute = [&](std::string_view name, const std::optional<bool>& p, const std::optional<bool>& q) {
        r.value(ChangeKind::dc_attribute_changed, attr(path, name), name, flag(p), flag(q), px, py);
    };
    attribute("UnknownFRMW", x.unknown_frmw, y.unknown_frmw);
    attribute("Unknown64Bit", x.unknown_64bit, y.unknown_64bit);
    attribute("ExternalRefClock", x.external_ref_clock, y.external_ref_clock);
    attribute("PotentialReferenceClock", x.potential_reference_clock, y.potential_reference_clock);
    attribute("TimeLoopControlOnly", x.time_loop_control_only, y.time_loop_control_only);
    compare_extras(r, path, x.extras, y.extras, px, py);
}

}  // namespace esi::diff_detail
