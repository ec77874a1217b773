// NetworkSpec -> Network: resolve each slave's device in the library, read the ESI files that
// hold them (once each, through the load layer), configure every slave (slave_context.hpp) and
// lay out the process image.

#include <fmt/format.h>
#include <map>

#include "esi/device_selector.hpp"
#include "esi/load/document.hpp"
#include "esi/net/network.hpp"
#include "esi/net/resolve.hpp"
#include "slave_context.hpp"

namespace esi::net {

namespace fs = std::filesystem;

namespace {

// The ESI files of a build, each read once.
class DocumentStore {
public:
    const LoadedDocument* get(const std::string& path) {
        auto it = documents_.find(path);
        if (it == documents_.end()) it = documents_.emplace(path, std::make_shared<LoadedDocument>(load_document_file(path))).first;
        return it->second.get();
    }
    std::vector<std::shared_ptr<const EsiDocument>> keep_alive() {
        std::vector<std::shared_ptr<const EsiDocument>> out;
        for (auto& [path, loaded] : documents_)
            if (loaded->document) {
                // Aliasing constructor: the document lives as long as its LoadedDocument.
                out.emplace_back(loaded, &*loaded->document);
            }
        return out;
    }

private:
    std::map<std::string, std::shared_ptr<LoadedDocument>> documents_;
};

std::string default_name(const Device& device, std::size_t position) {
    return fmt::format("Term {} ({})", position + 1, device.type.text.empty() ? "device" : device.type.text);
}

}  // namespace

BuildResult build_network(const NetworkSpec& spec, const LibraryIndex& index) {
    BuildResult result;
    Diagnostics& diagnostics = result.diagnostics;
    Network net;
    net.name = fs::path(spec.path).stem().string();
    net.path = spec.path;
    net.master = spec.master;
    DocumentStore store;

    for (std::size_t i = 0; i < spec.slaves.size(); ++i) {
        const SlaveSpec& ss = spec.slaves[i];
        DeviceQuery query{ss.device, ss.vendor_id, ss.product_code, ss.revision};
        Resolution resolution = resolve_device(index, query, spec.path, ss.device_pos);
        diagnostics.append(std::move(resolution.diagnostics));
        if (!resolution.device) continue;
        const IndexedDevice& found = *resolution.device;
        const std::string& file = index.file_of(found).path;
        const LoadedDocument* loaded = store.get(file);
        if (!loaded->usable()) {
            Diagnostic& d = diagnostics.emplace(Severity::error, "net-esi-unusable", "cannot use the ESI file that describes " + describe_identity(found),
                                                spec.path, ss.device_pos);
            for (const Diagnostic& e : loaded->diagnostics)
                if (e.severity == Severity::error && d.notes.size() < 5) d.notes.push_back({e.path, e.pos, e.message});
            continue;
        }
        const std::vector<const Device*> devices = select_devices(*loaded->document, std::nullopt);
        const Device* device = found.ordinal < devices.size() ? devices[found.ordinal] : nullptr;
        if (!device || device->type.product_code != found.product_code || device->type.revision_no != found.revision_no) {
            diagnostics.emplace(Severity::error, "net-index-stale",
                                file + " changed since it was indexed; run again to index it anew", spec.path, ss.device_pos);
            continue;
        }
        const EtherCATInfo* info = loaded->document->info_of(*device);

        NetworkSlave slave;
        slave.position = i;
        slave.name = ss.name.empty() ? default_name(*device, i) : ss.name;
        slave.phys_addr = static_cast<std::uint16_t>(1001 + i);
        slave.auto_inc_addr = static_cast<std::uint16_t>((0x10000 - i) & 0xFFFF);
        slave.alias = ss.alias;
        slave.device = device;
        slave.info = info;
        slave.esi_path = file;
        slave.vendor_id = info && info->vendor ? info->vendor->id.value_or(0) : 0;
        slave.product_code = device->type.product_code.value_or(0);
        slave.revision = device->type.revision_no.value_or(0);
        slave.physics = device->physics;
        slave.ros2_interfaces = ss.ros2_interfaces;

        Limits limits;
        for (const auto& [selector, device_limits] : loaded->device_limits)
            if (selector.matches(*device)) limits.merge(device_limits);
        limits.merge(ss.limits);
        SlaveContext context{spec, ss, slave, *device, *info, limits, diagnostics};
        configure_modules(context);
        select_pdos(context);
        configure_pdo_entries(context);
        setup_sync_managers(context);
        setup_dc(context, spec.master);
        build_coe_init_cmds(context, spec.master);
        check_ros2_interfaces(context);
        net.slaves.push_back(std::move(slave));
    }
    if (spec.slaves.empty())
        diagnostics.emplace(Severity::warning, "net-empty", "the network has no slaves; only the master is configured", spec.path, {});
    check_topology(net, spec, diagnostics);
    if (diagnostics.has_errors()) return result;

    for (NetworkSlave& s : net.slaves)
        if (s.dc && !net.reference_clock) {
            s.dc->reference_clock = true;
            net.reference_clock = s.position;
        }
    layout_process_image(net, diagnostics, spec.path);
    if (diagnostics.has_errors()) return result;
    net.documents = store.keep_alive();
    result.network = std::move(net);
    return result;
}

BuildResult build_network(const NetworkSpec& spec, const BuildOptions& options) {
    std::vector<fs::path> roots;
    const fs::path base = fs::path(spec.path).parent_path();
    for (const std::string& e : spec.esi) roots.push_back(fs::path(e).is_absolute() ? fs::path(e) : base / e);
    for (const fs::path& e : options.extra_esi) roots.push_back(e);
    if (roots.empty()) {
        BuildResult result;
        result.diagnostics.emplace(Severity::error, "net-no-esi", "no ESI files to look in: give 'esi:' in the network file or --esi",
                                   spec.path, spec.esi_pos);
        return result;
    }
    IndexResult indexed = build_library_index(roots, options.index);
    if (indexed.diagnostics.has_errors()) {
        BuildResult result;
        result.diagnostics = std::move(indexed.diagnostics);
        result.index_stats = indexed.stats;
        return result;
    }
    BuildResult result = build_network(spec, indexed.index);
    indexed.diagnostics.append(std::move(result.diagnostics));
    result.diagnostics = std::move(indexed.diagnostics);
    result.index_stats = indexed.stats;
    return result;
}

}  // namespace esi::net
