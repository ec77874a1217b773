// ros2/ec_modules.ros2_control.xacro: the ros2_control system that loads every slave_config
// through ethercat_driver_ros2, as the driver's documentation shows it: one component per slave
// (a <joint> for a CiA 402 drive, driven by EcCiA402Drive, else a <gpio> with GenericEcSlave),
// its state and command interfaces, and the <ec_module> with alias, position and slave_config.
//
// It is one xacro macro, `<network>_ec_modules`, with the folder of the slave_configs as a
// parameter, because the path a robot package installs them to is the package's choice.
// xacro evaluates "${…}" and "$(…)" in any attribute or text, so a '$' that a slave name
// brings is doubled ("$$" is xacro's escape) and can never run as an expression.

#include <fmt/format.h>

#include <cctype>

#include "esi/net/ros2_config.hpp"
#include "ros2_channels.hpp"
#include "xml_text.hpp"

namespace esi::net {

namespace {

std::string xacro_literal(std::string_view text) {
    std::string out;
    for (char c : text) {
        out += c;
        if (c == '$') out += '$';
    }
    return out;
}

std::string macro_name(std::string_view network) {
    std::string out;
    for (char c : network) {
        const unsigned char u = static_cast<unsigned char>(c);
        out += (u < 0x80 && (std::isalnum(u) || c == '_')) ? c : '_';
    }
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out.front()))) out.insert(out.begin(), '_');
    return out + "_ec_modules";
}

}  // namespace

std::string write_ros2_control_xacro(const Network& n) {
    XmlText x;
    x.comment(fmt::format(" ethercat_driver_ros2 system of network '{}', written by esi-net. Include this file and call "
                          "<xacro:{} config_dir=\"…\"/> with the folder the slave configs are installed to. ",
                          xacro_literal(n.name), macro_name(n.name)));
    x.open("robot", {{"xmlns:xacro", "http://www.ros.org/wiki/xacro"}});
    x.open("xacro:macro", {{"name", macro_name(n.name)}, {"params", "config_dir master_id:=0"}});
    x.open("ros2_control", {{"name", xacro_literal(n.name.empty() ? "ethercat" : n.name)}, {"type", "system"}});
    x.open("hardware");
    x.leaf("plugin", "ethercat_driver/EthercatDriver");
    x.leaf("param", "${master_id}", {{"name", "master_id"}});
    x.leaf("param", fmt::format("{}", 1e6 / n.master.cycle_time_us), {{"name", "control_frequency"}});
    x.close();
    const std::vector<std::string> files = ros2_config_file_names(n);
    for (std::size_t i = 0; i < n.slaves.size(); ++i) {
        const NetworkSlave& s = n.slaves[i];
        const Ros2Plan plan = plan_ros2_slave(s, n.path);
        x.open(plan.slave.cia402 ? "joint" : "gpio", {{"name", xacro_literal(s.name)}});
        for (const Ros2Pdo& p : plan.slave.tpdo)
            for (const Ros2Channel& c : p.channels)
                if (c.interface) x.empty("state_interface", {{"name", xacro_literal(*c.interface)}});
        for (const Ros2Pdo& p : plan.slave.rpdo)
            for (const Ros2Channel& c : p.channels)
                if (c.interface) x.empty("command_interface", {{"name", xacro_literal(*c.interface)}});
        if (plan.slave.cia402) x.empty("command_interface", {{"name", "reset_fault"}});
        x.open("ec_module", {{"name", xacro_literal(s.name)}});
        x.leaf("plugin", plan.slave.cia402 ? "ethercat_generic_plugins/EcCiA402Drive" : "ethercat_generic_plugins/GenericEcSlave");
        // IgH addresses a slave with an alias as (alias, 0), as the IgH output does.
        x.leaf("param", std::to_string(s.alias.value_or(0)), {{"name", "alias"}});
        x.leaf("param", std::to_string(s.alias && *s.alias ? 0 : s.position), {{"name", "position"}});
        x.leaf("param", "${config_dir}/" + xacro_literal(files[i]), {{"name", "slave_config"}});
        x.close();
        x.close();
    }
    return x.finish();
}

}  // namespace esi::net
