// Virtual slaves from a device source, an ESI file or a network file.

#include "esi/sim/slave_setup.hpp"

#include <fmt/format.h>

#include "esi/io/read_file.hpp"
#include "esi/load/document.hpp"
#include "esi/net/network.hpp"
#include "esi/net/network_spec.hpp"
#include "esi/plural.hpp"
#include "esi/sii/build.hpp"
#include "slotted_device.hpp"

namespace esi::sim {

namespace {

[[nodiscard]] std::string identity_text(const Device& device) {
    return fmt::format("{} (product code 0x{:08X}, revision 0x{:08X})", device.type.text,
                       device.type.product_code.value_or(0), device.type.revision_no.value_or(0));
}

[[nodiscard]] const EtherCATInfo* info_of(const EsiDocument& document, const Device& device) {
    for (const EtherCATInfo& info : document.infos)
        for (const Device& candidate : info.devices)
            if (&candidate == &device) return &info;
    return nullptr;
}

}  // namespace

bool is_network_file(const std::string& bytes) {
    std::size_t at = 0;
    while (at < bytes.size()) {
        if (bytes.compare(at, 7, "slaves:") == 0) return true;
        at = bytes.find('\n', at);
        if (at == std::string::npos) break;
        ++at;
    }
    return false;
}

std::optional<VirtualSlave> build_slave(const EtherCATInfo& info, const Device& device, const SlaveOptions& options,
                                        const StackFactory& stacks, const std::string& path, Diagnostics& diagnostics) {
    std::vector<std::uint8_t> image;
    if (options.eeprom) {
        image = *options.eeprom;
    } else {
        sii::BuildResult built = sii::build_image(info, device, {}, path);
        if (!built.ok()) {
            for (const Diagnostic& d : built.diagnostics)
                if (d.severity == Severity::error) diagnostics.add(d);
            return std::nullopt;
        }
        image = std::move(built.bytes);
    }
    VirtualSlave slave;
    slave.name = device.type.text;
    slave.vendor_id = info.vendor && info.vendor->id ? *info.vendor->id : 0;
    slave.product_code = device.type.product_code.value_or(0);
    slave.revision = device.type.revision_no.value_or(0);
    slave.esc = std::make_unique<esc::Esc>(std::move(image), options.esc);
    if (stacks) slave.stack = stacks(info, options.firmware ? *options.firmware : device, diagnostics);
    return slave;
}

LineResult line_from_source(const std::filesystem::path& source, const SourceOptions& options, const StackFactory& stacks) {
    LineResult result;
    const std::string path = source.string();
    LoadedDocument loaded = load_document_file(source);
    if (!loaded.usable()) {
        result.diagnostics.append(std::move(loaded.diagnostics));
        if (!result.diagnostics.has_errors())
            result.diagnostics.emplace(Severity::error, "sim-source", "the file cannot be used as a device source", path, {});
        return result;
    }
    // An ESI file's rule findings are the vendor's business; the simulator reports what stops it.
    auto document = std::make_shared<const EsiDocument>(std::move(*loaded.document));
    const std::vector<const Device*> devices = select_devices(*document, options.device);
    if (devices.empty()) {
        result.diagnostics.emplace(Severity::error, "sim-device",
                                   options.device ? "no device matches --device" : "the file describes no device", path, {});
        return result;
    }
    if (devices.size() > 1) {
        Diagnostic& d = result.diagnostics.emplace(
            Severity::error, "sim-device",
            fmt::format("the file describes {}: choose one with --device PRODUCTCODE[:REVISION]", esi::counted(devices.size(), "device")),
            path, {});
        for (const Device* device : devices) d.notes.push_back({path, device->pos, identity_text(*device)});
        return result;
    }
    const Device& device = *devices.front();
    const EtherCATInfo* info = info_of(*document, device);
    SlaveOptions slave_options;
    if (options.eeprom) {
        std::string error;
        std::optional<std::string> bytes = read_file_bytes(*options.eeprom, error);
        if (!bytes) {
            result.diagnostics.emplace(Severity::error, "io-error", error, options.eeprom->string(), {});
            return result;
        }
        slave_options.eeprom = std::vector<std::uint8_t>(bytes->begin(), bytes->end());
    }
    std::optional<VirtualSlave> slave = build_slave(*info, device, slave_options, stacks, path, result.diagnostics);
    if (!slave || result.diagnostics.has_errors()) return result;
    Line line;
    line.keep(document);
    line.add(std::move(*slave));
    result.line = std::move(line);
    return result;
}

LineResult line_from_network(const std::filesystem::path& network, const StackFactory& stacks) {
    LineResult result;
    net::NetworkFileResult file = net::read_network_file(network.string());
    result.diagnostics.append(std::move(file.diagnostics));
    if (!file.spec) return result;
    net::BuildResult built = net::build_network(*file.spec, net::BuildOptions{});
    for (const Diagnostic& d : built.diagnostics)
        if (d.severity == Severity::error) result.diagnostics.add(d);
    if (!built.network) return result;
    Line line;
    for (const auto& document : built.network->documents) line.keep(document);
    for (const net::NetworkSlave& slave : built.network->slaves) {
        const Device firmware = device_with_modules(slave);
        SlaveOptions options;
        options.firmware = &firmware;
        std::optional<VirtualSlave> virtual_slave =
            build_slave(*slave.info, *slave.device, options, stacks, slave.esi_path, result.diagnostics);
        if (!virtual_slave) continue;
        line.add(std::move(*virtual_slave));
    }
    if (result.diagnostics.has_errors()) return result;
    result.line = std::move(line);
    return result;
}

}  // namespace esi::sim
