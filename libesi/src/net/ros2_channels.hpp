#pragma once
// How ethercat_driver_ros2 (ICube-Robotics) sees one slave's process data: its rpdo and tpdo
// lists of channels, each with the driver's type, bit mask and ros2_control interface. Shared
// by the build step that checks NETWORK.yaml's `ros2_interfaces` and the ROS 2 writer.
//
// What the driver does with a channel (ethercat_interface, ec_pdo_channel_manager): it
// registers every entry with IgH and reads or writes the value at the entry's *byte* offset in
// the domain; a `bool` is the byte ANDed with `mask`; the bit position IgH returns is not used.
// So an entry of 8 bits or more that does not start on a byte cannot feed an interface, and a
// 1-bit entry needs the mask of its bit within its byte.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

struct Ros2Channel {
    const ConfiguredEntry* entry = nullptr;
    std::string type;                  // bool, bitN, int8 … uint64, float, double
    std::optional<std::uint8_t> mask;  // bool and bitN entries inside one byte
    std::optional<std::string> interface;
    std::optional<double> factor, offset, default_value;
    std::string note;  // why an entry that carries data has no interface
};

struct Ros2Pdo {
    const ConfiguredPdo* pdo = nullptr;
    std::vector<Ros2Channel> channels;
};

struct Ros2Slave {
    bool cia402 = false;  // EcCiA402Drive rather than GenericEcSlave
    std::vector<Ros2Pdo> rpdo, tpdo;  // in SM assignment order
};

// Problems of the driver's format itself (PDOs of one direction on two SMs, an entry over 255
// bits) are `structural`; those of NETWORK.yaml's ros2_interfaces (an entry the slave does not
// map, an interface on an entry the driver cannot read) are `overrides`, located there.
struct Ros2Plan {
    Ros2Slave slave;
    Diagnostics structural;
    Diagnostics overrides;
};

[[nodiscard]] Ros2Plan plan_ros2_slave(const NetworkSlave& slave, const std::string& network_path);

// True when the slave is driven as a CiA 402 axis: its mailbox declares profile 402, or it maps
// both the controlword 0x6040 and the statusword 0x6041.
[[nodiscard]] bool is_cia402_drive(const NetworkSlave& slave);

}  // namespace esi::net
