#pragma once
// Building virtual slaves from the model: a device's SII image (built by the sii layer, or a
// given EEPROM file), the ESC that loads it, and the slave stack a factory makes for the device.
// Two ways to a line: one device from a YAML source or an ESI file (`--device` as in esi-gen),
// or every slave of esi-net's NETWORK.yaml, resolved as `esi-net build` resolves them.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/esc/esc.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/sim/line.hpp"

namespace esi::sim {

// The firmware for a device: esi-sim passes the model slave (model_slave.hpp); tests pass their
// own. May return null (an ESC without firmware) and report why in the diagnostics.
using StackFactory =
    std::function<std::unique_ptr<esc::SlaveStack>(const EtherCATInfo& info, const Device& device, Diagnostics& diagnostics)>;

struct SlaveOptions {
    std::optional<std::vector<std::uint8_t>> eeprom;  // the image as given; else built from the device
    esc::EscConfig esc;
    // The device the firmware serves when it is not the one the EEPROM describes: a modular
    // device with the modules in its slots (the SII image describes the device alone).
    const Device* firmware = nullptr;
};

// One virtual slave for `device` (one of info.devices). Errors (an image the sii layer refuses)
// leave the result empty; `path` locates them.
[[nodiscard]] std::optional<VirtualSlave> build_slave(const EtherCATInfo& info, const Device& device,
                                                      const SlaveOptions& options, const StackFactory& stacks,
                                                      const std::string& path, Diagnostics& diagnostics);

struct SourceOptions {
    std::optional<DeviceSelector> device;            // --device
    std::optional<std::filesystem::path> eeprom;     // --eeprom
};

struct LineResult {
    std::optional<Line> line;  // absent on error
    Diagnostics diagnostics;
};

// SOURCE [--device] [--eeprom]: a line of one slave. A file that describes several devices
// needs --device; a selector that matches none, or several, is an error. A modular device runs
// with its default modules in their slots (the model slave places them as esi-net would).
[[nodiscard]] LineResult line_from_source(const std::filesystem::path& source, const SourceOptions& options,
                                          const StackFactory& stacks);

// NETWORK.yaml: its slaves in order, each device resolved from the network's `esi:` files.
[[nodiscard]] LineResult line_from_network(const std::filesystem::path& network, const StackFactory& stacks);

// A YAML file with a top-level `slaves:` key is a network file; anything else is a device source
// or an ESI file.
[[nodiscard]] bool is_network_file(const std::string& bytes);

}  // namespace esi::sim
