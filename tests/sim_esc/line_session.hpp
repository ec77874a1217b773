#pragma once
// Test helper: lines of virtual slaves as esi-sim builds them (a device from a source or ESI file,
// optionally from a given EEPROM image; or a NETWORK.yaml), with the model slave as firmware, for
// the LineMaster to drive.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "esi/sim/line.hpp"
#include "sim_esc/sim_fixtures.hpp"

namespace esi::test {

// `d`'s device as `esi-sim SOURCE --device SELECTOR [--eeprom IMAGE] [--echo]` runs it; absent
// (with `error` set) when the library refuses.
std::optional<sim::Line> device_line(const ModelDevice& d, const std::optional<std::vector<std::uint8_t>>& eeprom, bool echo,
                                     std::string& error);
// `esi-sim NETWORK.yaml [--echo]`.
std::optional<sim::Line> network_line(const std::filesystem::path& network, bool echo, std::string& error);

// Every sample device (samples/*.yaml), sorted by file.
std::vector<ModelDevice> sample_devices();
// The image a sample runs from: samples whose ConfigData has no PDI (PDI control 0) get one
// that enables SPI, with the checksum made right (the firmware needs an interface to its ESC).
std::vector<std::uint8_t> runnable_image(const ModelDevice& d);

// The one device of samples/FILE on a line (with runnable_image), or `error` why not.
struct SampleLine {
    std::vector<ModelDevice> devices;  // the file's devices; the line runs the first
    std::optional<sim::Line> line;
    std::string error;
};
SampleLine sample_line(const std::string& file, bool echo);

}  // namespace esi::test
