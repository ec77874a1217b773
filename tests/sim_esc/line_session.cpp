#include "sim_esc/line_session.hpp"

#include <algorithm>

#include "esi/sim/model_slave.hpp"
#include "esi/sim/slave_setup.hpp"
#include "support/test_support.hpp"

namespace esi::test {

namespace {

sim::StackFactory model_slaves(bool echo) {
    return [echo](const EtherCATInfo& info, const Device& device, Diagnostics& diagnostics) {
        return sim::make_model_slave(info, device, {.echo = echo}, diagnostics);
    };
}

std::optional<sim::Line> taken(sim::LineResult built, std::string& error) {
    for (const Diagnostic& d : built.diagnostics)
        if (d.severity == Severity::error) error += format_diagnostic(d);
    return std::move(built.line);
}

}  // namespace

std::optional<sim::Line> device_line(const ModelDevice& d, const std::optional<std::vector<std::uint8_t>>& eeprom, bool echo,
                                     std::string& error) {
    sim::SourceOptions options;
    options.device = DeviceSelector{d.product_code, d.revision};
    std::optional<TempDir> dir;
    if (eeprom) {
        dir.emplace();
        write_bytes(*dir / "eeprom.bin", *eeprom);
        options.eeprom = *dir / "eeprom.bin";
    }
    return taken(sim::line_from_source(d.file, options, model_slaves(echo)), error);
}

std::optional<sim::Line> network_line(const std::filesystem::path& network, bool echo, std::string& error) {
    return taken(sim::line_from_network(network, model_slaves(echo)), error);
}

std::vector<ModelDevice> sample_devices() {
    std::vector<ModelDevice> out;
    for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "samples"))
        if (entry.path().extension() == ".yaml")
            for (ModelDevice& d : model_devices(entry.path())) out.push_back(std::move(d));
    std::sort(out.begin(), out.end(), [](const ModelDevice& a, const ModelDevice& b) { return a.file < b.file; });
    return out;
}

std::vector<std::uint8_t> runnable_image(const ModelDevice& d) {
    return d.image[0] == 0 ? with_config_word0(d.image, 0x05, d.image[1]) : d.image;
}

SampleLine sample_line(const std::string& file, bool echo) {
    SampleLine out;
    out.devices = model_devices(source_dir() / "samples" / file);
    if (out.devices.size() != 1) {
        out.error = file + ": " + std::to_string(out.devices.size()) + " devices, one expected";
        return out;
    }
    out.line = device_line(out.devices[0], runnable_image(out.devices[0]), echo, out.error);
    return out;
}

}  // namespace esi::test
