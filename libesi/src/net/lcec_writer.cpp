// lcec.xml: a linuxcnc-ethercat configuration with one `generic` slave per device, in the
// shape lcec_configgen writes from a bus scan (golden files in the corpus) — syncManager, pdo
// and pdoEntry with halPin and halType — plus what the ESI knows and a bus scan does not: the
// DC op mode (dcConf), the ESC watchdog and the start-up SDOs (sdoConfig).
//
// Two maintained forks read this file, and each stops at an attribute or value it does not know
// (its parser has no "ignore unknown"): linuxcnc-ethercat/linuxcnc-ethercat (the default, where
// lcec_configgen lives) has no `refClockSlaveIdx` and reads `float-double-ieee`;
// sittner/linuxcnc-ethercat takes `refClockSlaveIdx` but not `float-double-ieee`. Neither has
// a 64-bit HAL type, so a 64-bit entry stays mapped (the mapping is the ESI's) without a pin,
// and says so in a comment, rather than getting a pin of the wrong width.
//
// Pin names follow lcec_configgen: the entry's name in lower case, runs of other characters
// as '-', "pin-<index>-<sub>" for an unnamed entry; a name used twice in a slave gets the last
// word of its PDO's name in front. HAL types follow the entry's data type as lcec_configgen
// infers them from SDO information: under 8 bits "bit"; 8–32-bit integers "u32"/"s32"; 64-bit
// integers "u64"/"s64"; REAL "float-ieee", LREAL "float-double-ieee". Padding entries are kept
// (without a pin) so that the mapping lcec configures is the ESI's.

#include <fmt/format.h>
#include <algorithm>
#include <map>
#include <optional>

#include "esi/data_types.hpp"
#include "esi/net/outputs.hpp"
#include "esi/plural.hpp"
#include "xml_text.hpp"

namespace esi::net {

namespace {

std::string pin_text(std::string_view text) {
    std::string out;
    bool dash = false;
    for (char c : text) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x80 && std::isalnum(u)) {
            out += static_cast<char>(std::tolower(u));
            dash = false;
        } else if (!dash) {
            out += '-';
            dash = true;
        }
    }
    return out;
}

std::string trim_dashes(std::string s) {
    while (!s.empty() && s.front() == '-') s.erase(s.begin());
    while (!s.empty() && s.back() == '-') s.pop_back();
    return s;
}

// The HAL type of an entry as lcec_configgen infers it, or nullopt when the fork has none for it.
std::optional<std::string> hal_type(const ConfiguredEntry& e, LcecFork fork) {
    if (e.bit_len < 8) return "bit";
    const BasicType* basic = find_basic_type(e.data_type);
    if (!basic) basic = find_basic_type(standard_type_name_for(e.data_type));
    if (basic && basic->type_class == TypeClass::real) {
        if (e.bit_len == 32) return "float-ieee";
        if (e.bit_len == 64 && fork == LcecFork::linuxcnc_ethercat) return "float-double-ieee";
        return std::nullopt;
    }
    if (e.bit_len > 32) return std::nullopt;
    const bool is_signed = basic && basic->type_class == TypeClass::signed_integer;
    return is_signed ? "s32" : "u32";
}

std::string_view fork_name(LcecFork fork) { return fork == LcecFork::sittner ? "sittner" : "linuxcnc-ethercat"; }

std::string hex_attr(std::uint32_t v, int digits) { return fmt::format("{:0{}x}", v, digits); }

}  // namespace

std::string write_lcec(const Network& n) {
    const LcecFork fork = n.master.lcec_fork;
    XmlText x;
    x.drop_declaration();
    x.comment(fmt::format("for github.com/{0}/linuxcnc-ethercat (NETWORK.yaml master.lcec_fork: {0})",
                          fork == LcecFork::sittner ? "sittner" : "linuxcnc-ethercat"));
    x.open("masters");
    const std::uint64_t cycle_ns = std::uint64_t{n.master.cycle_time_us} * 1000;
    XmlText::Attributes master = {{"idx", "0"}, {"appTimePeriod", std::to_string(cycle_ns)}, {"refClockSyncCycles", "1"}};
    if (n.reference_clock && fork == LcecFork::sittner) master.emplace_back("refClockSlaveIdx", std::to_string(*n.reference_clock));
    x.open("master", master);
    if (n.reference_clock && fork != LcecFork::sittner)
        x.comment(fmt::format("DC reference clock: slave {} in the ENI; this fork has no refClockSlaveIdx, IgH takes the first "
                              "DC-capable slave (lcec_fork: sittner writes it)",
                              *n.reference_clock));
    for (const NetworkSlave& s : n.slaves) {
        std::string name = trim_dashes(pin_text(s.name));
        if (name.empty()) name = "d" + std::to_string(s.position + 1);
        x.open("slave", {{"idx", std::to_string(s.position)},
                         {"type", "generic"},
                         {"vid", fmt::format("0x{:08x}", s.vendor_id)},
                         {"pid", fmt::format("0x{:08x}", s.product_code)},
                         {"configPdos", "true"},
                         {"name", name}});
        x.comment(s.device->type.text);
        if (s.dc) {
            XmlText::Attributes dc = {{"assignActivate", fmt::format("0x{:04x}", s.dc->assign_activate)}};
            dc.emplace_back("sync0Cycle", s.dc->cycle_time0 % cycle_ns == 0 ? "*" + std::to_string(s.dc->cycle_time0 / cycle_ns)
                                                                             : std::to_string(s.dc->cycle_time0));
            dc.emplace_back("sync0Shift", std::to_string(s.dc->shift_time0));
            if (s.dc->cycle_time1) dc.emplace_back("sync1Cycle", std::to_string(s.dc->cycle_time1));
            x.empty("dcConf", dc);
        }
        if (s.watchdog_divider || s.sm_watchdog)
            x.empty("watchdog", {{"divider", std::to_string(s.watchdog_divider.value_or(0))}, {"intervals", std::to_string(s.sm_watchdog.value_or(0))}});
        for (const CoeCommand& c : s.coe_init_cmds) {
            // lcec configures PDOs itself (configPdos); it sends SDOs while configuring the slave.
            if (c.generated()) continue;
            if (std::none_of(c.transitions.begin(), c.transitions.end(), [](const std::string& t) { return t == "IP" || t == "PS" || t == "SO"; }))
                continue;
            if (!c.comment.empty()) x.comment(c.comment);
            x.open("sdoConfig", {{"idx", hex_attr(c.index, 4)}, {"subIdx", c.complete_access ? std::string("complete") : hex_attr(c.subindex, 2)}});
            std::string data;
            for (std::uint8_t b : c.data) data += fmt::format("{}{:02X}", data.empty() ? "" : " ", b);
            x.empty("sdoDataRaw", {{"data", data}});
            x.close();
        }

        // Pin names, made unique within the slave.
        std::map<std::string, int> count;
        auto base_pin = [](const ConfiguredEntry& e) {
            const std::string name = trim_dashes(pin_text(e.name));
            return name.empty() ? fmt::format("pin-{:04x}-{:02x}", e.index, e.subindex) : name;
        };
        for (const ConfiguredPdo& p : s.pdos)
            for (const ConfiguredEntry& e : p.entries)
                if (!e.is_padding()) ++count[base_pin(e)];
        std::map<std::string, int> used;
        for (const SmSetup& sm : s.sms) {
            const char* dir = (sm.control_byte & 0x0C) == 0x04 ? "out" : "in";
            if (sm.pdos.empty()) {
                x.empty("syncManager", {{"idx", std::to_string(sm.number)}, {"dir", dir}});
                continue;
            }
            x.open("syncManager", {{"idx", std::to_string(sm.number)}, {"dir", dir}});
            for (std::size_t pi : sm.pdos) {
                const ConfiguredPdo& p = s.pdos[pi];
                x.open("pdo", {{"idx", hex_attr(p.index, 4)}});
                if (!p.name.empty()) x.comment(p.name);
                for (const ConfiguredEntry& e : p.entries) {
                    XmlText::Attributes a = {{"idx", hex_attr(e.index, 4)}, {"subIdx", hex_attr(e.subindex, 2)}, {"bitLen", std::to_string(e.bit_len)}};
                    const std::optional<std::string> type = e.is_padding() ? std::nullopt : hal_type(e, fork);
                    if (!e.is_padding() && !type)
                        x.comment(fmt::format("0x{:04X}:{:02X} ({}) has no HAL pin: {} has no HAL type for it", e.index, e.subindex,
                                              esi::counted(e.bit_len, "bit"), fork_name(fork)));
                    if (type) {
                        std::string pin = base_pin(e);
                        if (count[pin] > 1) {
                            const std::size_t space = p.name.rfind(' ');
                            const std::string prefix = trim_dashes(pin_text(space == std::string::npos ? std::string(dir) : p.name.substr(space + 1)));
                            pin = prefix + "-" + pin;
                        }
                        if (const int n_used = used[pin]++; n_used > 0) pin += "-" + std::to_string(n_used + 1);
                        a.emplace_back("halPin", pin);
                        a.emplace_back("halType", *type);
                    }
                    x.empty("pdoEntry", a);
                }
                x.close();
            }
            x.close();
        }
        x.close();
    }
    return x.finish();
}

}  // namespace esi::net
