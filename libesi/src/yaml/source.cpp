// load_device_source(): bytes -> bounded tree (libyaml events) -> model -> derivation.
// The input is bounded three ways while the tree is built (size, nesting depth, nodes after
// alias expansion), so hostile input fails fast with a located message; nothing throws across
// the API, and nothing is returned as a document when there are errors.

#include "esi/yaml/source.hpp"

#include <set>

#include "esi/derive/derive.hpp"
#include "esi/io/read_file.hpp"
#include "yaml/extras.hpp"
#include "esi/yaml/tree.hpp"
#include "yaml/source_parser.hpp"

namespace esi {

namespace yaml {

std::optional<Vendor> SourceParser::vendor(const Node& node) {
    const auto f = r_.mapping(node, Context::vendor, "vendor");
    if (!f) return std::nullopt;
    Vendor v;
    v.pos = f->pos();
    if (r_.require(*f, "id", "vendor")) {
        v.id = r_.integer<std::uint32_t>(*f->find("id"), "id");
        v.id_pos = pos_of(*f->find("id"));
    }
    if (r_.require(*f, "name", "vendor")) v.names = names_of(*f, "name");
    v.comments = names_of(*f, "comment");
    v.urls = names_of(*f, "url");
    r_.optional_text(*f, "description_url", v.description_url);
    images(*f, v.images);
    r_.optional_text(*f, "unique_name", v.unique_name);
    r_.optional_text(*f, "file_version", v.file_version);
    extras(*f, "xml", v.extras);
    return v;
}

std::optional<Group> SourceParser::group(const Node& node) {
    const auto f = r_.mapping(node, Context::group, "a group");
    if (!f) return std::nullopt;
    Group g;
    g.pos = f->pos();
    if (r_.require(*f, "type", "a group")) {
        g.type = r_.text(*f->find("type"), "type").value_or("");
        g.type_pos = pos_of(*f->find("type"));
    }
    if (r_.require(*f, "name", "a group")) g.names = names_of(*f, "name");
    g.comments = names_of(*f, "comment");
    r_.optional_integer(*f, "sort_order", g.sort_order);
    r_.optional_text(*f, "parent_group", g.parent_group);
    images(*f, g.images);
    extras(*f, "xml", g.extras);
    return g;
}

std::optional<EtherCATInfo> SourceParser::parse(const Node& root, std::vector<ParsedDevice>& devices,
                                                std::vector<ParsedModule>& modules) {
    const auto f = r_.mapping(root, Context::root, "the device source");
    if (!f) return std::nullopt;
    EtherCATInfo info;
    info.pos = f->pos();
    info.has_descriptions = true;
    info.descriptions_pos = info.pos;
    r_.optional_text(*f, "esi_version", info.version);
    // A module description file (EtherCATModule root: Vendor and Modules, ETG.2000) has no devices.
    module_file_ = false;
    if (const Node* n = f->find("root_element")) {
        const auto root_element = r_.text(*n, "root_element");
        if (root_element == "EtherCATModule") module_file_ = true;
        else if (root_element && *root_element != "EtherCATInfo")
            r_.error(*n, "yaml-value", "'root_element' is EtherCATInfo (the default) or EtherCATModule, not '" + *root_element + "'");
    }
    if (r_.require(*f, "vendor", "the device source")) info.vendor = vendor(*f->find("vendor"));
    if (const Node* n = f->find("groups")) {
        if (auto items = r_.sequence(*n, "groups")) {
            std::map<std::string, SourcePos> seen;
            for (const auto& item : *items) {
                auto g = group(item);
                if (!g) continue;
                if (const auto [it, inserted] = seen.emplace(g->type, g->type_pos); !inserted) {
                    Diagnostic& d = r_.error(g->type_pos, "yaml-duplicate", "the group '" + g->type + "' is declared twice");
                    d.notes.push_back({r_.path(), it->second, "first declared here"});
                    continue;
                }
                info.groups.push_back(std::move(*g));
            }
        }
    }
    if (const Node* n = f->find("modules")) {
        if (auto items = r_.sequence(*n, "modules")) {
            std::map<std::uint32_t, SourcePos> idents;
            for (const auto& item : *items) {
                auto m = module(item);
                if (!m) continue;
                if (const auto [it, inserted] = idents.emplace(m->module.module_ident, m->module.type_pos); !inserted) {
                    Diagnostic& d = r_.error(m->module.pos, "yaml-duplicate", "two modules have the ident " + format_hex(m->module.module_ident, 8));
                    d.notes.push_back({r_.path(), it->second, "the other module"});
                }
                modules.push_back(std::move(*m));
            }
        }
        info.has_modules = true;
    }
    const std::optional<std::uint32_t> vendor_id = info.vendor ? info.vendor->id : std::nullopt;
    const std::string* only_group = info.groups.size() == 1 ? &info.groups.front().type : nullptr;
    if (module_file_) {
        if (f->has("devices")) r_.error(*f->key_node("devices"), "yaml-conflict", "a module description file (EtherCATModule) has no devices");
        if (!f->has("modules")) r_.error(f->node(), "yaml-missing-key", "a module description file (EtherCATModule) needs 'modules'");
        info.has_descriptions = false;
    } else if (r_.require(*f, "devices", "the device source")) {
        if (auto items = r_.sequence(*f->find("devices"), "devices")) {
            if (items->empty()) r_.error(*f->find("devices"), "yaml-value", "'devices' lists at least one device");
            std::map<std::pair<std::uint32_t, std::uint32_t>, SourcePos> identities;
            for (const auto& item : *items) {
                auto d = device(item, vendor_id, modules, info.groups.size(), only_group);
                if (!d) continue;
                const auto& t = d->device.type;
                if (t.product_code && t.revision_no) {
                    // One (product code, revision) pair is one device.
                    if (const auto [it, inserted] = identities.emplace(std::pair{*t.product_code, *t.revision_no}, d->device.pos);
                        !inserted) {
                        Diagnostic& diag = r_.error(d->device.pos, "yaml-duplicate",
                                                    "two devices have product code " + format_hex(*t.product_code, 8) + " and revision " +
                                                        format_hex(*t.revision_no, 8));
                        diag.notes.push_back({r_.path(), it->second, "the other device"});
                    }
                }
                devices.push_back(std::move(*d));
            }
        }
    }
    extras(*f, "xml", info.extras);
    extras(*f, "descriptions_xml", info.descriptions_extras);
    return info;
}

}  // namespace yaml

DeviceSource load_device_source(std::string_view bytes, const std::string& path, const DeviceSourceOptions& options) {
    DeviceSource out;
    Diagnostics& diagnostics = out.diagnostics;
    try {
        if (bytes.size() > options.max_bytes) {
            diagnostics.emplace(Severity::error, "yaml-too-large",
                                "the file has " + std::to_string(bytes.size()) + " bytes; a device source may have at most " +
                                    std::to_string(options.max_bytes),
                                path, SourcePos{});
            return out;
        }
        std::string text(bytes);
        if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
            static_cast<unsigned char>(text[2]) == 0xBF)
            text.erase(0, 3);
        auto source = std::make_shared<SourceText>(path, text);
        out.source = source;
        if (const auto nul = text.find('\0'); nul != std::string::npos) {
            diagnostics.emplace(Severity::error, "yaml-syntax", "NUL character in the file (is it a YAML text file?)", path,
                                source->position_of(nul));
            return out;
        }
        yaml::TreeLimits limits;
        limits.max_depth = options.max_depth;
        limits.max_nodes = options.max_nodes;
        bool empty = false;
        const std::unique_ptr<yaml::Tree> tree = yaml::Tree::parse(text, path, limits, diagnostics, empty);
        if (empty && !diagnostics.has_errors())
            diagnostics.emplace(Severity::error, "yaml-missing-key", "the file is empty; a device source needs vendor and devices",
                                path, SourcePos{1, 1});
        if (!tree) {
            diagnostics.sort();
            return out;
        }
        const yaml::Node root(tree->root());

        yaml::Reader reader(path, diagnostics);
        yaml::SourceParser parser(reader, *source);
        std::vector<yaml::ParsedDevice> devices;
        std::vector<yaml::ParsedModule> modules;
        std::optional<EtherCATInfo> info = parser.parse(root, devices, modules);
        if (info && !diagnostics.has_errors()) {
            std::vector<bool> with_groups;
            for (auto& d : devices) {
                derive_device(d.device, d.intent, path, diagnostics);
                with_groups.push_back(d.intent.options.groups);
                if (d.limits && d.device.type.product_code)
                    out.device_limits.emplace_back(DeviceSelector{*d.device.type.product_code, d.device.type.revision_no}, *d.limits);
            }
            // A module's host is the first device whose slots take it.
            for (auto& m : modules) {
                const Device* host = nullptr;
                for (const auto& d : devices) {
                    if (host) break;
                    if (!d.device.slots) continue;
                    for (const auto& slot : d.device.slots->slots)
                        for (const auto& id : slot.module_idents)
                            if (id.value == m.module.module_ident) host = &d.device;
                }
                derive_module(m.module, m.intent, host, path, diagnostics);
                info->modules.push_back(std::move(m.module));
            }
            for (auto& d : devices) info->devices.push_back(std::move(d.device));
            derive_groups(*info, with_groups);
        }
        diagnostics.sort();
        if (!info || diagnostics.has_errors()) return out;

        EsiDocument document;
        document.kind = parser.module_file() ? DocumentKind::ethercat_module : DocumentKind::ethercat_info;
        document.path = path;
        document.encoding = SourceEncoding::utf8;
        document.root_pos = info->pos;
        document.infos.push_back(std::move(*info));
        document.source = source;
        out.document = std::move(document);
    } catch (const std::exception& e) {
        // The standard library may throw (bad_alloc); the API promises values, so the failure
        // becomes a diagnostic.
        out.document.reset();
        diagnostics.emplace(Severity::error, "yaml-internal", std::string("the YAML source could not be processed: ") + e.what(), path,
                            SourcePos{});
    }
    return out;
}

DeviceSource load_device_source_file(const std::filesystem::path& path, const DeviceSourceOptions& options) {
    std::string error;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > options.max_bytes) {
        DeviceSource out;
        out.diagnostics.emplace(Severity::error, "yaml-too-large",
                                "the file has " + std::to_string(size) + " bytes; a device source may have at most " +
                                    std::to_string(options.max_bytes),
                                path.string(), SourcePos{});
        return out;
    }
    // Bounded while reading too: a path that is a pipe or a device announces no size.
    const std::optional<std::string> bytes = read_file_bytes(path, error, options.max_bytes);
    if (!bytes) {
        DeviceSource out;
        out.diagnostics.emplace(Severity::error, "io-error", "cannot read file: " + error, path.string(), SourcePos{});
        return out;
    }
    return load_device_source(*bytes, path.string(), options);
}

}  // namespace esi
