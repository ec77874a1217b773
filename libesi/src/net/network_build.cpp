// NetworkSpec -> Network: resolve each slave's device in the library, read the ESI files that
// hold them (once each, through the load layer), configure every slave (slave_context.hpp) and
// lay out the process image.

#include <fmt/format.h>
#include <algorithm>
#include <map>

#include "esi/device_selector.hpp"
#include "esi/load/document.hpp"
#include "esi/net/network.hpp"
#include "esi/net/resolve.hpp"
#include "esi/plural.hpp"
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

// The slave at position `i` configured from `found`; nullopt (with errors) when it cannot be.
std::optional<NetworkSlave> configure_slave(const NetworkSpec& spec, const SlaveSpec& ss, std::size_t i, const LibraryIndex& index,
                                            const IndexedDevice& found, DocumentStore& store, Diagnostics& diagnostics) {
    const std::string& file = index.file_of(found).path;
    const LoadedDocument* loaded = store.get(file);
    if (!loaded->usable()) {
        Diagnostic& d = diagnostics.emplace(Severity::error, "net-esi-unusable", "cannot use the ESI file that describes " + describe_identity(found),
                                            spec.path, ss.device_pos);
        for (const Diagnostic& e : loaded->diagnostics)
            if (e.severity == Severity::error && d.notes.size() < 5) d.notes.push_back({e.path, e.pos, e.message});
        return std::nullopt;
    }
    const std::vector<const Device*> devices = select_devices(*loaded->document, std::nullopt);
    const Device* device = found.ordinal < devices.size() ? devices[found.ordinal] : nullptr;
    const EtherCATInfo* info = device ? loaded->document->info_of(*device) : nullptr;
    // The index may come from the cache: what it said must be what the file holds now.
    const bool file_has_vendor = info && info->vendor && info->vendor->id.has_value();
    const bool vendor_differs = file_has_vendor ? !found.vendor_id || *found.vendor_id != *info->vendor->id : found.vendor_id.has_value();
    if (!device || !info || device->type.product_code != found.product_code || device->type.revision_no != found.revision_no ||
        vendor_differs || device->type.text != found.type) {
        diagnostics.emplace(Severity::error, "net-index-stale", file + " changed while it was being read; run again", spec.path,
                            ss.device_pos);
        return std::nullopt;
    }

    NetworkSlave slave;
    slave.position = i;
    slave.name = ss.name.empty() ? default_name(*device, i) : ss.name;
    slave.phys_addr = static_cast<std::uint16_t>(1001 + i);
    slave.auto_inc_addr = static_cast<std::uint16_t>((0x10000 - i) & 0xFFFF);
    slave.alias = ss.alias;
    slave.device = device;
    slave.info = info;
    slave.esi_path = file;
    slave.vendor_id = info->vendor ? info->vendor->id.value_or(0) : 0;
    slave.product_code = device->type.product_code.value_or(0);
    slave.revision = device->type.revision_no.value_or(0);
    slave.physics = device->physics;
    slave.ros2_interfaces = ss.ros2_interfaces;

    Limits limits;
    for (const auto& [selector, device_limits] : loaded->device_limits)
        if (selector.matches(*device)) limits.merge(device_limits);
    limits.merge(ss.limits);
    const std::size_t errors_before = diagnostics.count(Severity::error);
    SlaveContext context{spec, ss, slave, *device, *info, limits, diagnostics};
    check_reader_errors(context, devices, loaded->diagnostics);
    configure_modules(context);
    select_pdos(context);
    configure_pdo_entries(context);
    setup_sync_managers(context);
    setup_dc(context, spec.master);
    build_coe_init_cmds(context, spec.master);
    check_ros2_interfaces(context);
    check_representable(context);
    if (diagnostics.count(Severity::error) != errors_before) return std::nullopt;
    return slave;
}

// `esi_file:` names which of several files describing the identity to take.
const IndexedDevice* pick_file(const NetworkSpec& spec, const SlaveSpec& ss, const LibraryIndex& index,
                               const std::vector<const IndexedDevice*>& candidates, Diagnostics& diagnostics) {
    const fs::path wanted = fs::path(*ss.esi_file).is_absolute() ? fs::path(*ss.esi_file) : fs::path(spec.path).parent_path() / *ss.esi_file;
    for (const IndexedDevice* d : candidates) {
        std::error_code ec;
        if (fs::equivalent(wanted, index.file_of(*d).path, ec)) return d;
    }
    Diagnostic& d = diagnostics.emplace(Severity::error, "net-device-duplicate",
                                        "'esi_file' names no file that describes " + describe_identity(*candidates.front()), spec.path,
                                        ss.esi_file_pos);
    for (const IndexedDevice* c : candidates) d.notes.push_back({index.file_of(*c).path, SourcePos{c->line, c->column}, "it is described here"});
    return nullptr;
}

// Several files describe the slave's identity: taking the first is fine when every one gives the
// master the same configuration (an info says which was taken); otherwise the choice would be
// silent and may be wrong, so the slave is refused until `esi_file:` picks one.
bool same_configuration(const NetworkSpec& spec, const SlaveSpec& ss, std::size_t i, const LibraryIndex& index,
                        const std::vector<const IndexedDevice*>& candidates, const NetworkSlave& taken, DocumentStore& store,
                        Diagnostics& diagnostics) {
    const std::string fingerprint = configuration_fingerprint(taken);
    std::vector<const IndexedDevice*> different;
    for (std::size_t c = 1; c < candidates.size(); ++c) {
        Diagnostics scratch;
        const std::optional<NetworkSlave> other = configure_slave(spec, ss, i, index, *candidates[c], store, scratch);
        if (!other || configuration_fingerprint(*other) != fingerprint) different.push_back(candidates[c]);
    }
    const IndexedDevice& first = *candidates.front();
    auto note = [&](const IndexedDevice* d, std::string what) {
        return DiagnosticNote{index.file_of(*d).path, SourcePos{d->line, d->column}, std::move(what)};
    };
    if (different.empty()) {
        Diagnostic& d = diagnostics.emplace(Severity::info, "net-device-duplicate",
                                            fmt::format("{} is described by {} that configure it alike; taken from {} (the first in "
                                                        "the order of 'esi:' and --esi)",
                                                        describe_identity(first), esi::counted(candidates.size(), "file"), index.file_of(first).path),
                                            spec.path, ss.device_pos);
        for (std::size_t c = 1; c < candidates.size(); ++c) d.notes.push_back(note(candidates[c], "also described here"));
        return true;
    }
    Diagnostic& d = diagnostics.emplace(Severity::error, "net-device-duplicate",
                                        fmt::format("{} is described by {} that configure it differently; pick one with "
                                                    "'esi_file:'",
                                                    describe_identity(first), esi::counted(candidates.size(), "file")),
                                        spec.path, ss.device_pos);
    d.notes.push_back(note(&first, "first in the order of 'esi:' and --esi"));
    for (const IndexedDevice* c : different) d.notes.push_back(note(c, "configures it differently"));
    return false;
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
    if (spec.slaves.size() > max_network_slaves) {
        diagnostics.emplace(Severity::error, "net-too-many-slaves",
                            fmt::format("{}; an EtherCAT segment addresses at most {} (station addresses 1001 to 65535)",
                                        esi::counted(spec.slaves.size(), "slave"), max_network_slaves),
                            spec.path, spec.slaves[max_network_slaves].pos);
        return result;
    }

    for (std::size_t i = 0; i < spec.slaves.size(); ++i) {
        const SlaveSpec& ss = spec.slaves[i];
        DeviceQuery query{ss.device, ss.vendor_id, ss.product_code, ss.revision};
        Resolution resolution = resolve_device(index, query, spec.path, ss.device_pos);
        diagnostics.append(std::move(resolution.diagnostics));
        if (!resolution.device) continue;
        std::vector<const IndexedDevice*> candidates{resolution.device};
        candidates.insert(candidates.end(), resolution.duplicates.begin(), resolution.duplicates.end());
        if (ss.esi_file) {
            const IndexedDevice* picked = pick_file(spec, ss, index, candidates, diagnostics);
            if (!picked) continue;
            candidates = {picked};
        }
        std::optional<NetworkSlave> slave = configure_slave(spec, ss, i, index, *candidates.front(), store, diagnostics);
        if (!slave) continue;
        if (candidates.size() > 1 && !same_configuration(spec, ss, i, index, candidates, *slave, store, diagnostics)) continue;
        net.slaves.push_back(std::move(*slave));
    }
    if (spec.slaves.empty())
        diagnostics.emplace(Severity::warning, "net-empty", "the network has no slaves; only the master is configured", spec.path, {});
    resolve_topology(net, spec, diagnostics);
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
    const bool stale = std::any_of(result.diagnostics.begin(), result.diagnostics.end(),
                                   [](const Diagnostic& d) { return d.rule == "net-index-stale"; });
    if (stale && indexed.stats.cached > 0) {
        // The cache disagreed with a file: the result must not depend on it, so every file is
        // indexed anew and the network built again.
        BuildOptions fresh = options;
        fresh.index.rescan = true;
        return build_network(spec, fresh);
    }
    indexed.diagnostics.append(std::move(result.diagnostics));
    result.diagnostics = std::move(indexed.diagnostics);
    result.index_stats = indexed.stats;
    return result;
}

}  // namespace esi::net
