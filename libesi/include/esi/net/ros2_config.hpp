#pragma once
// The ROS 2 output of esi-net: what ICube-Robotics' ethercat_driver_ros2 loads (docs/esi-net.md).
//
//   ros2/<slave>.yaml                 one slave_config per slave: vendor_id, product_id,
//                                     assign_activate, sdo, rpdo/tpdo channels, sm
//   ros2/ec_modules.ros2_control.xacro  a xacro macro with the <ros2_control> system: one gpio
//                                     (or, for CiA 402 drives, joint) per slave with its
//                                     interfaces and the <ec_module> that loads its slave_config
//
// The driver cannot express everything an ENI can (PDOs of one direction on two SMs, start-up
// SDOs other than 1/2/4/8-byte downloads in PREOP); such a network is refused (errors) or the
// command is left out with a warning and a comment in the file.

#include <filesystem>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

struct Ros2Output {
    std::vector<OutputFile> files;  // empty when diagnostics has errors
    Diagnostics diagnostics;
};

// The file name of a slave's config: its name with every character but [A-Za-z0-9._-] as '_',
// made unique in the network with "-2", "-3" … (bus order).
[[nodiscard]] std::vector<std::string> ros2_config_file_names(const Network& network);
[[nodiscard]] std::string write_ros2_slave_config(const Network& network, std::size_t slave, Diagnostics& diagnostics);
[[nodiscard]] std::string write_ros2_control_xacro(const Network& network);
// Every file under `directory`/ros2.
[[nodiscard]] Ros2Output ros2_outputs(const Network& network, const std::filesystem::path& directory);

}  // namespace esi::net
