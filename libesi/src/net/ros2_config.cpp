// ros2/<slave>.yaml: one ethercat_driver_ros2 slave_config per slave, in the format of the
// driver's documentation (config_generic_slave.rst) and its example configurations.
//
// The driver configures PDOs itself through IgH (ecrt_slave_config_pdos from rpdo, tpdo and sm),
// so the ENI's generated assignment and mapping commands are not repeated; the other start-up
// SDOs go to `sdo`, which the driver reads as {index, sub_index, type, value} with the value as a
// C int: each is written as the signed integer of its bytes (int8/int16/int32, and int64 when
// the 8 bytes are a sign-extended int). What `sdo` cannot carry (complete access, other sizes,
// commands not sent in PREOP) is a comment in the file and a warning.

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <optional>
#include <cmath>

#include "esi/net/ros2_config.hpp"
#include "esi/plural.hpp"
#include "ros2_channels.hpp"
#include "slave_context.hpp"
#include "yaml_scalar.hpp"

namespace esi::net {

namespace {

std::string number_text(double v) {
    if (std::isnan(v)) return ".nan";
    if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
    return fmt::format("{}", v);
}

std::string channel_line(const Ros2Channel& c, bool rx) {
    const ConfiguredEntry& e = *c.entry;
    std::string line = fmt::format("{{index: 0x{:04x}, sub_index: 0x{:02x}, type: {}", e.index, e.subindex, c.type);
    if (c.mask && c.interface) line += fmt::format(", mask: {}", *c.mask);
    if (c.interface) line += fmt::format(", {}: {}", rx ? "command_interface" : "state_interface", yaml_quoted(*c.interface));
    if (c.default_value && rx) line += ", default: " + number_text(*c.default_value);
    if (c.factor) line += ", factor: " + number_text(*c.factor);
    if (c.offset) line += ", offset: " + number_text(*c.offset);
    line += "}";
    if (!e.is_padding()) {
        line += "  # " + yaml_comment_text(e.name.empty() ? e.data_type : e.name);
        if (!c.note.empty()) line += " (no interface: " + c.note + ")";
    }
    return line;
}

void write_pdos(std::string& y, const char* key, const std::vector<Ros2Pdo>& pdos, bool rx) {
    if (pdos.empty()) return;
    y += fmt::format("{}:  # {}\n", key, rx ? "RxPDO: master to slave" : "TxPDO: slave to master");
    for (const Ros2Pdo& p : pdos) {
        y += fmt::format("  - index: 0x{:04x}", p.pdo->index);
        if (!p.pdo->name.empty()) y += "  # " + yaml_comment_text(p.pdo->name);
        y += p.channels.empty() ? "\n    channels: []\n" : "\n    channels:\n";
        for (const Ros2Channel& c : p.channels) y += "      - " + channel_line(c, rx) + "\n";
    }
}

// A start-up command as the driver's `sdo` entry, or why it cannot be one.
std::optional<std::string> sdo_entry(const CoeCommand& c, std::string& why) {
    const bool in_preop = std::any_of(c.transitions.begin(), c.transitions.end(), [](const std::string& t) { return t == "IP" || t == "PS"; });
    if (!in_preop) {
        why = "not sent on the way to SAFEOP";
        return std::nullopt;
    }
    if (c.complete_access) {
        why = "complete access";
        return std::nullopt;
    }
    const std::size_t n = c.data.size();
    if (n != 1 && n != 2 && n != 4 && n != 8) {
        why = esi::counted(n, "byte");
        return std::nullopt;
    }
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < n; ++i) raw |= std::uint64_t{c.data[i]} << (8 * i);
    std::int64_t value = 0;
    if (n == 8) value = static_cast<std::int64_t>(raw);
    else value = static_cast<std::int64_t>(raw << (64 - 8 * n)) >> (64 - 8 * n);  // sign-extend
    if (value < std::numeric_limits<std::int32_t>::min() || value > std::numeric_limits<std::int32_t>::max()) {
        why = "a 64-bit value beyond what the driver reads (a C int)";
        return std::nullopt;
    }
    return fmt::format("{{index: 0x{:04x}, sub_index: 0x{:02x}, type: int{}, value: {}}}", c.index, c.subindex, 8 * n, value);
}

std::string safe_file_stem(std::string_view name) {
    std::string out;
    for (char c : name) {
        const unsigned char u = static_cast<unsigned char>(c);
        out += (u < 0x80 && (std::isalnum(u) || c == '.' || c == '_' || c == '-')) ? c : '_';
    }
    // Never a hidden file, "." or "..".
    if (out.empty() || out.front() == '.') out.insert(out.begin(), '_');
    return out;
}

}  // namespace

std::vector<std::string> ros2_config_file_names(const Network& n) {
    std::vector<std::string> names;
    for (const NetworkSlave& s : n.slaves) {
        const std::string stem = safe_file_stem(s.name);
        std::string name = stem;
        for (int k = 2; std::find(names.begin(), names.end(), name + ".yaml") != names.end(); ++k) name = stem + "-" + std::to_string(k);
        names.push_back(name + ".yaml");
    }
    return names;
}

std::string write_ros2_slave_config(const Network& n, std::size_t index, Diagnostics& diagnostics) {
    const NetworkSlave& s = n.slaves[index];
    Ros2Plan plan = plan_ros2_slave(s, n.path);
    diagnostics.append(std::move(plan.structural));
    std::string y;
    y += fmt::format("# ethercat_driver_ros2 slave_config of {} ({}), position {}, written by esi-net from\n", yaml_comment_text(s.name),
                     yaml_comment_text(s.device->type.text), s.position);
    y += "# " + yaml_comment_text(std::filesystem::path(s.esi_path).filename().string()) + "\n";
    y += fmt::format("vendor_id: 0x{:08x}\nproduct_id: 0x{:08x}\n", s.vendor_id, s.product_code);
    if (s.dc) y += fmt::format("assign_activate: 0x{:04x}  # DC: {}\n", s.dc->assign_activate, yaml_comment_text(s.dc->op_mode));
    std::string sdos, left_out;
    for (const CoeCommand& c : s.coe_init_cmds) {
        if (c.generated()) continue;  // the driver configures PDOs itself
        std::string why;
        const std::string comment = c.comment.empty() ? "" : "  # " + yaml_comment_text(c.comment);
        if (const auto entry = sdo_entry(c, why)) {
            sdos += "  - " + *entry + comment + "\n";
            continue;
        }
        left_out += fmt::format("#   {}:{:02X} ({}){}\n", hex_index(c.index), c.subindex, why, comment);
        diagnostics.emplace(Severity::warning, "net-ros2-sdo",
                            fmt::format("slave '{}': start-up SDO {}:{:02X} is left out of ros2/ ({}); ethercat_driver_ros2 cannot send it",
                                        s.name, hex_index(c.index), c.subindex, why),
                            n.path, SourcePos{});
    }
    if (!sdos.empty()) y += "sdo:  # start-up SDOs, downloaded in PREOP\n" + sdos;
    if (!left_out.empty()) y += "# Start-up SDOs the driver cannot send (send them from the application):\n" + left_out;
    write_pdos(y, "rpdo", plan.slave.rpdo, true);
    write_pdos(y, "tpdo", plan.slave.tpdo, false);
    y += "sm:  # SyncManagers\n";
    for (const SmSetup& sm : s.sms) {
        const bool output = (sm.control_byte & 0x0C) == 0x04;
        const char* pdo = sm.pdos.empty() ? "~" : output ? "rpdo" : "tpdo";
        y += fmt::format("  - {{index: {}, type: {}, pdo: {}, watchdog: {}}}\n", sm.number, output ? "output" : "input", pdo,
                         (sm.control_byte & 0x40) ? "enable" : "disable");
    }
    return y;
}

Ros2Output ros2_outputs(const Network& n, const std::filesystem::path& directory) {
    Ros2Output out;
    const std::filesystem::path dir = directory / "ros2";
    const std::vector<std::string> names = ros2_config_file_names(n);
    for (std::size_t i = 0; i < n.slaves.size(); ++i) out.files.push_back({dir / names[i], write_ros2_slave_config(n, i, out.diagnostics)});
    out.files.push_back({dir / "ec_modules.ros2_control.xacro", write_ros2_control_xacro(n)});
    if (out.diagnostics.has_errors()) out.files.clear();
    return out;
}

}  // namespace esi::net
