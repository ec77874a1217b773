// The ROS 2 view of a slave: driver types, masks and interface names of every mapped entry.
//
// Interface names: a CiA 402 drive's first-axis objects get the names ethercat_driver_ros2's
// EcCiA402Drive and its example configurations use (position, velocity, effort,
// mode_of_operation …); the controlword gets the default 0 the plugin's state machine starts
// from and the mode of operation the cyclic synchronous mode of the mapped target. Any other
// entry is named after its ESI entry name (lower case, other characters as '_'), with its PDO's
// name in front when that name is used twice in the slave (EL1008: channel_1.input …); the
// component in the URDF is the slave, so the name needs no slave prefix. NETWORK.yaml's
// `ros2_interfaces` overrides both.

#include "ros2_channels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <map>
#include <set>

#include "esi/data_types.hpp"
#include "esi/plural.hpp"
#include "slave_context.hpp"

namespace esi::net {

namespace {

struct Cia402Name {
    std::uint32_t index;
    PdoDirection direction;
    const char* name;  // nullptr: no interface
};

// The driver's conventional names (EcCiA402Drive, its tests and example drive configurations).
constexpr Cia402Name cia402_names[] = {
    {0x6040, PdoDirection::rx, "control_word"},      {0x6060, PdoDirection::rx, "mode_of_operation"},
    {0x607A, PdoDirection::rx, "position"},          {0x60FF, PdoDirection::rx, "velocity"},
    {0x6071, PdoDirection::rx, "effort"},            {0x6041, PdoDirection::tx, "status_word"},
    {0x6061, PdoDirection::tx, "mode_of_operation"}, {0x6064, PdoDirection::tx, "position"},
    {0x606C, PdoDirection::tx, "velocity"},          {0x6077, PdoDirection::tx, "effort"},
};

std::string name_text(std::string_view text) {
    std::string out;
    bool sep = false;
    for (char c : text) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x80 && std::isalnum(u)) {
            if (sep && !out.empty()) out += '_';
            out += static_cast<char>(std::tolower(u));
            sep = false;
        } else {
            sep = true;
        }
    }
    return out;
}

// The driver's type for an entry; empty when it has none (the entry is then written as bitN).
std::string driver_type(const ConfiguredEntry& e) {
    if (e.is_padding()) return fmt::format("bit{}", e.bit_len);
    if (e.bit_len == 1) return "bool";
    const BasicType* basic = find_basic_type(e.data_type);
    if (!basic) basic = find_basic_type(standard_type_name_for(e.data_type));
    const TypeClass cls = basic ? basic->type_class : TypeClass::bit_string;
    if (cls == TypeClass::real) {
        if (e.bit_len == 32) return "float";
        if (e.bit_len == 64) return "double";
    }
    const bool integral = cls == TypeClass::signed_integer || cls == TypeClass::unsigned_integer || cls == TypeClass::bit_string ||
                          cls == TypeClass::bit || cls == TypeClass::boolean;
    if (integral && (e.bit_len == 8 || e.bit_len == 16 || e.bit_len == 32 || e.bit_len == 64))
        return fmt::format("{}int{}", cls == TypeClass::signed_integer ? "" : "u", e.bit_len);
    return fmt::format("bit{}", e.bit_len);
}

const Ros2InterfaceSpec* override_for(const NetworkSlave& s, const ConfiguredEntry& e) {
    for (const Ros2InterfaceSpec& o : s.ros2_interfaces)
        if (o.index == e.index && o.subindex == e.subindex) return &o;
    return nullptr;
}

}  // namespace

bool is_cia402_drive(const NetworkSlave& s) {
    if (s.mailbox)
        for (const auto& [profile, add_info] : s.mailbox->channel_info)
            if (profile == 402) return true;
    bool control = false, status = false;
    for (const ConfiguredPdo& p : s.pdos)
        for (const ConfiguredEntry& e : p.entries) {
            control = control || (e.index == 0x6040 && p.direction == PdoDirection::rx);
            status = status || (e.index == 0x6041 && p.direction == PdoDirection::tx);
        }
    return control && status;
}

Ros2Plan plan_ros2_slave(const NetworkSlave& s, const std::string& network_path) {
    Ros2Plan plan;
    plan.slave.cia402 = is_cia402_drive(s);
    auto structural = [&](std::string rule, std::string message) {
        plan.structural.emplace(Severity::error, std::move(rule), "slave '" + s.name + "': " + message, network_path, SourcePos{});
    };

    // Entry names used twice get their PDO's name in front.
    std::map<std::string, int> uses;
    for (const ConfiguredPdo& p : s.pdos)
        for (const ConfiguredEntry& e : p.entries)
            if (!e.is_padding()) ++uses[name_text(e.name)];

    bool mapped_target = false, mapped_velocity = false, mapped_torque = false;
    for (const ConfiguredPdo& p : s.pdos)
        for (const ConfiguredEntry& e : p.entries)
            if (p.direction == PdoDirection::rx) {
                mapped_target = mapped_target || e.index == 0x607A;
                mapped_velocity = mapped_velocity || e.index == 0x60FF;
                mapped_torque = mapped_torque || e.index == 0x6071;
            }

    std::set<std::string> used_names[2];
    std::optional<std::uint32_t> sm_of[2];
    for (const SmSetup& sm : s.sms) {
        std::uint32_t bit = 0;  // from the start of the SM's data, which IgH places on a byte
        for (std::size_t pi : sm.pdos) {
            const ConfiguredPdo& p = s.pdos[pi];
            const int dir = p.direction == PdoDirection::rx ? 0 : 1;
            // Pre-ETG.2000 catalogues refer to shared PDO definitions (RxPdo Ref=…) that carry no
            // index or entries here: a config without them would map nothing.
            if (p.index == 0)
                structural("net-ros2-layout", "its ESI gives a PDO without an index (a pre-ETG.2000 catalogue's PDO reference); "
                                              "name a revision from a current catalogue");
            if (sm_of[dir] && *sm_of[dir] != sm.number)
                structural("net-ros2-layout", fmt::format("its {} sit on SM{} and SM{}; ethercat_driver_ros2 assigns all {} to one SM",
                                                          dir == 0 ? "RxPDOs" : "TxPDOs", *sm_of[dir], sm.number, dir == 0 ? "rpdo" : "tpdo"));
            sm_of[dir] = sm.number;
            Ros2Pdo out;
            out.pdo = &p;
            for (const ConfiguredEntry& e : p.entries) {
                Ros2Channel c;
                c.entry = &e;
                c.type = driver_type(e);
                const std::uint32_t in_byte = bit % 8;
                bit += e.bit_len;
                if (e.bit_len > 255) {
                    structural("net-ros2-layout", fmt::format("entry {}:{:02X} has {}; the driver's channel length is 8 bits wide",
                                                              hex_index(e.index), e.subindex, esi::counted(e.bit_len, "bit")));
                    continue;
                }
                if (e.is_padding()) {
                    out.channels.push_back(std::move(c));
                    continue;
                }
                const bool small = e.bit_len < 8;
                const bool readable = small ? in_byte + e.bit_len <= 8 : in_byte == 0 && c.type.rfind("bit", 0) != 0;
                if (small && readable) c.mask = static_cast<std::uint8_t>(((1u << e.bit_len) - 1) << in_byte);
                std::optional<std::string> name;
                if (plan.slave.cia402 && e.subindex == 0)
                    for (const Cia402Name& n : cia402_names)
                        if (n.index == e.index && n.direction == p.direction && n.name) name = n.name;
                if (plan.slave.cia402 && p.direction == PdoDirection::rx && e.subindex == 0) {
                    if (e.index == 0x6040) c.default_value = 0;
                    if (e.index == 0x607A) c.default_value = std::numeric_limits<double>::quiet_NaN();
                    if (e.index == 0x6060) c.default_value = mapped_target ? 8 : mapped_velocity ? 9 : mapped_torque ? 10 : 8;
                }
                if (!name) {
                    std::string base = name_text(e.name);
                    if (base.empty()) base = fmt::format("entry_{:04x}_{:02x}", e.index, e.subindex);
                    else if (uses[base] > 1 && !name_text(p.name).empty()) base = name_text(p.name) + "." + base;
                    name = base;
                }
                // A bit field wider than 1 bit is read masked but not shifted by the driver: no
                // interface unless the user names one, knowing that.
                if (small && e.bit_len > 1) name.reset();
                if (!readable) {
                    name.reset();
                    c.note = e.bit_len < 8 ? "crosses a byte boundary" : in_byte != 0 ? "does not start on a byte" : "has no driver type";
                }
                if (const Ros2InterfaceSpec* o = override_for(s, e)) {
                    if (o->no_interface) name.reset();
                    if (o->name) {
                        if (!readable)
                            plan.overrides.emplace(Severity::error, "net-ros2-interface",
                                                   fmt::format("entry {}:{:02X} {}: ethercat_driver_ros2 reads whole bytes from an entry's byte "
                                                               "offset and would not read it correctly",
                                                               hex_index(e.index), e.subindex, c.note),
                                                   network_path, o->pos);
                        else name = o->name;
                    }
                    if (o->factor) c.factor = o->factor;
                    if (o->offset) c.offset = o->offset;
                    if (o->default_value) {
                        if (p.direction == PdoDirection::tx)
                            plan.overrides.emplace(Severity::error, "net-ros2-interface",
                                                   fmt::format("entry {}:{:02X} is an input (TxPDO); 'default' is for outputs", hex_index(e.index), e.subindex),
                                                   network_path, o->pos);
                        c.default_value = o->default_value;
                    }
                }
                if (name) {
                    std::string unique = *name;
                    for (int k = 2; !used_names[dir].insert(unique).second; ++k) unique = *name + "." + std::to_string(k);
                    c.interface = unique;
                }
                out.channels.push_back(std::move(c));
            }
            (dir == 0 ? plan.slave.rpdo : plan.slave.tpdo).push_back(std::move(out));
        }
    }
    return plan;
}

void check_ros2_interfaces(SlaveContext& context) {
    const NetworkSlave& s = context.slave;
    for (const Ros2InterfaceSpec& o : s.ros2_interfaces) {
        bool mapped = false;
        for (const ConfiguredPdo& p : s.pdos)
            for (const ConfiguredEntry& e : p.entries) mapped = mapped || (!e.is_padding() && e.index == o.index && e.subindex == o.subindex);
        if (!mapped)
            context.error(o.pos, "net-ros2-interface",
                          fmt::format("entry {}:{:02X} is not in the PDOs assigned to '{}'", hex_index(o.index), o.subindex, s.name));
    }
    if (s.ros2_interfaces.empty()) return;
    Ros2Plan plan = plan_ros2_slave(s, context.network.path);
    context.diagnostics.append(std::move(plan.overrides));
}

}  // namespace esi::net
