// The DC op mode of one slave (ETG.2000 Dc/OpMode). Without `dc:` a slave runs in its ESI's
// first op mode, as TwinCAT and EC-Engineer configure a new device (corpus: the Elmo drives in
// DC Sync, CherryECAT's drive in "Synchron"). An op mode whose AssignActivate is 0 is no DC.
// CycleTimeSync0 with a Factor is that multiple of the master cycle (a negative Factor divides);
// without one, its value in ns (0: the master cycle).

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

#include "esi/yaml/reader.hpp"
#include "slave_context.hpp"

namespace esi::net {

namespace {

bool same_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::int64_t sync_time(const std::optional<DcTime>& t, std::int64_t base_ns) {
    if (!t) return 0;
    if (t->factor && *t->factor > 0) return base_ns * *t->factor;
    if (t->factor && *t->factor < 0) return base_ns / -*t->factor;
    return t->value != 0 ? t->value : base_ns;
}

}  // namespace

void setup_dc(SlaveContext& c, const MasterSpec& master) {
    const std::vector<DcOpMode> none;
    const std::vector<DcOpMode>& modes = c.device.dc ? c.device.dc->op_modes : none;
    const DcOpMode* mode = nullptr;
    if (c.spec.dc) {
        for (const DcOpMode& m : modes)
            if (m.name == *c.spec.dc) mode = &m;
        if (!mode)
            for (const DcOpMode& m : modes)
                if (same_ignoring_case(m.name, *c.spec.dc)) mode = &m;
        if (!mode) {
            std::vector<std::string_view> names;
            std::string list;
            for (const DcOpMode& m : modes) {
                names.push_back(m.name);
                list += (list.empty() ? "'" : ", '") + m.name + "'";
            }
            c.error(c.spec.dc_pos, "net-dc-op-mode",
                    modes.empty() ? c.device.type.text + " has no DC op modes"
                                  : "no DC op mode '" + *c.spec.dc + "'" + yaml::did_you_mean(*c.spec.dc, names) + "; " +
                                        c.device.type.text + " has " + list);
            return;
        }
        if (!master.dc && mode->assign_activate != 0) {
            c.error(c.spec.dc_pos, "net-dc-off", "'" + mode->name + "' uses distributed clocks, but the master has dc: false");
            return;
        }
    } else if (!modes.empty()) {
        mode = &modes.front();
        if (!master.dc && mode->assign_activate != 0) {
            mode = nullptr;
            for (const DcOpMode& m : modes)
                if (m.assign_activate == 0) {
                    mode = &m;
                    break;
                }
        }
    }
    if (!mode || mode->assign_activate == 0) return;
    const std::int64_t cycle_ns = static_cast<std::int64_t>(master.cycle_time_us) * 1000;
    DcSetup dc;
    dc.op_mode = mode->name;
    dc.assign_activate = static_cast<std::uint16_t>(mode->assign_activate);
    dc.cycle_time0 = static_cast<std::uint32_t>(std::clamp<std::int64_t>(sync_time(mode->cycle_time_sync0, cycle_ns), 0, 0xFFFFFFFF));
    // SYNC1 only when AssignActivate enables it (bit 10): its time counts from SYNC0.
    if (mode->assign_activate & 0x0400)
        dc.cycle_time1 = static_cast<std::uint32_t>(
            std::clamp<std::int64_t>(mode->cycle_time_sync1 ? sync_time(mode->cycle_time_sync1, dc.cycle_time0) : 0, 0, 0xFFFFFFFF));
    if (mode->shift_time_sync0) dc.shift_time0 = static_cast<std::int32_t>(mode->shift_time_sync0->value);
    c.slave.dc = dc;
}

}  // namespace esi::net
