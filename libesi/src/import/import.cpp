// import_device_source(): the file-level YAML and, per device, the choice of what to leave to
// derivation. The choice is checked, not guessed: a device is written with a part left out, the
// text is loaded again (load_device_source, which derives), and esi::diff_documents must find the
// device identical to the original; otherwise that part stays explicit with its derivation
// switched off (docs/yaml-import.md).

#include "esi/import/import.hpp"

#include <filesystem>
#include <map>

#include "esi/diff/diff.hpp"
#include "esi/yaml/source.hpp"
#include "import/import_writer.hpp"
#include "import/yaml_emitter.hpp"

namespace esi {

namespace {

using import_detail::ImportWriter;
using import_detail::OmitPlan;
using import_detail::YNode;

// The file around the devices: everything but `devices` (modules left out for a derivation
// check: slots name modules by ident, and only the device is compared).
YNode file_node(ImportWriter& w, const EsiDocument& document, const EtherCATInfo& info, bool with_modules = true) {
    YNode root = YNode::map();
    if (document.kind == DocumentKind::ethercat_module) root.set("root_element", YNode::text("EtherCATModule"));
    if (info.version) root.set("esi_version", YNode::text(*info.version));
    root.set("vendor", info.vendor ? w.vendor(*info.vendor) : YNode::map());
    if (!info.groups.empty()) {
        YNode groups = YNode::seq();
        for (const auto& g : info.groups) groups.push(w.group(g));
        root.set("groups", std::move(groups));
    }
    if (with_modules && (info.has_modules || !info.modules.empty())) {
        YNode modules = YNode::seq();
        for (const auto& m : info.modules) modules.push(w.module(m));
        root.set("modules", std::move(modules));
    }
    return root;
}

void finish(ImportWriter& w, YNode& root, const EtherCATInfo& info) {
    if (!info.extras.empty()) root.set("xml", w.extras(info.extras));
    if (!info.descriptions_extras.empty()) root.set("descriptions_xml", w.extras(info.descriptions_extras));
}

// The device written with `plan`, loaded again (with the file's modules and groups around it so
// that slots and group references resolve), compared with the original.
bool plan_reproduces(const EsiDocument& document, const EtherCATInfo& info, const Device& device, const OmitPlan& plan) {
    Diagnostics scratch;
    ImportWriter w(scratch);
    w.quiet = true;
    YNode root = file_node(w, document, info, false);
    YNode devices = YNode::seq();
    devices.push(w.device(device, info, plan));
    root.set("devices", std::move(devices));
    const DeviceSource loaded = load_device_source(root.render(), "import-check.yaml");
    if (!loaded.document || loaded.document->infos.empty() || loaded.document->infos.front().devices.size() != 1) return false;
    // Compare the one device: a document holding only it on each side.
    EsiDocument a;
    a.kind = DocumentKind::ethercat_info;
    a.infos.emplace_back();
    a.infos.front().vendor = info.vendor;
    a.infos.front().devices.push_back(device);
    EsiDocument b;
    b.kind = DocumentKind::ethercat_info;
    b.infos.emplace_back();
    b.infos.front().vendor = info.vendor;
    b.infos.front().devices.push_back(loaded.document->infos.front().devices.front());
    return diff_documents(a, b).identical();
}

OmitPlan choose_plan(const EsiDocument& document, const EtherCATInfo& info, const Device& device) {
    // Everything the device could leave to derivation at once: the common case (a file that
    // esi-gen wrote, or one that follows the ETG defaults) needs one check.
    OmitPlan all;
    all.data_link_layer = device.mailbox && device.mailbox->data_link_layer.value_or(false);
    all.sms = !device.sms.empty();
    all.fmmus = !device.fmmus.empty();
    all.pdo_assignment = !device.rx_pdos.empty() || !device.tx_pdos.empty();
    all.pdo_entries = all.pdo_assignment;
    const Dictionary* dict = device.dictionary();
    const bool objects = dict && !dict->objects.empty();
    all.device_type_object = objects && dict->find_object(0x1000);
    all.identity_object = objects && dict->find_object(0x1018);
    all.mapping_objects = objects;
    all.assignment_objects = objects;
    all.sm_types_object = objects && dict->find_object(0x1C00);
    all.data_types = dict && !dict->data_types.empty();
    if (!all.any()) return all;
    if (plan_reproduces(document, info, device, all)) return all;
    // One part at a time, then the parts that worked together (they may interact: SM sizes
    // follow the PDO assignment).
    OmitPlan chosen;
    bool OmitPlan::*parts[] = {&OmitPlan::data_link_layer,   &OmitPlan::sms,              &OmitPlan::fmmus,
                               &OmitPlan::pdo_assignment,    &OmitPlan::pdo_entries,      &OmitPlan::device_type_object,
                               &OmitPlan::identity_object,   &OmitPlan::mapping_objects,  &OmitPlan::assignment_objects,
                               &OmitPlan::sm_types_object,   &OmitPlan::data_types};
    for (auto part : parts) {
        if (!(all.*part)) continue;
        OmitPlan trial = chosen;
        trial.*part = true;
        if (plan_reproduces(document, info, device, trial)) chosen = trial;
    }
    return chosen;
}

}  // namespace

ImportResult import_device_source(const EsiDocument& document, const ImportOptions& options) {
    ImportResult out;
    if ((document.kind != DocumentKind::ethercat_info && document.kind != DocumentKind::ethercat_module) || document.infos.size() != 1) {
        out.diagnostics.emplace(Severity::error, "import-root",
                                "only an EtherCATInfo or EtherCATModule file can be imported (the YAML source describes one vendor's devices)",
                                document.path, document.root_pos);
        return out;
    }
    const EtherCATInfo& info = document.infos.front();
    ImportWriter w(out.diagnostics);
    YNode root = file_node(w, document, info);
    if (document.kind == DocumentKind::ethercat_info) {
        YNode devices = YNode::seq();
        // Two devices with one identity: the YAML source refuses that (yaml-duplicate) when it is
        // loaded; say so here already, naming both places in the ESI.
        std::map<std::pair<std::uint32_t, std::uint32_t>, const Device*> identities;
        for (const auto& d : info.devices) {
            if (options.device && !options.device->matches(d)) continue;
            if (d.type.product_code && d.type.revision_no) {
                const auto [it, inserted] = identities.emplace(std::pair{*d.type.product_code, *d.type.revision_no}, &d);
                if (!inserted) {
                    Diagnostic& diag = out.diagnostics.emplace(
                        Severity::warning, "import-identity",
                        "this device has the product code " + import_detail::hex_text(*d.type.product_code, 8) + " and revision " +
                            import_detail::hex_text(*d.type.revision_no, 8) + " of another; the YAML source declares an identity once, so it " +
                            "is refused until one of them changes",
                        document.path, d.type.pos.known() ? d.type.pos : d.pos);
                    diag.notes.push_back({document.path, it->second->type.pos.known() ? it->second->type.pos : it->second->pos,
                                          "the other device"});
                }
            }
            OmitPlan plan;
            if (options.omit_derived) plan = choose_plan(document, info, d);
            if (plan.any()) ++out.derived_devices;
            devices.push(w.device(d, info, plan));
            ++out.devices;
        }
        if (out.devices == 0) {
            out.diagnostics.emplace(Severity::error, "import-device",
                                    options.device ? "--device matches no device of the file" : "the file describes no device",
                                    document.path, document.root_pos);
            return out;
        }
        root.set("devices", std::move(devices));
    } else if (options.device) {
        out.diagnostics.emplace(Severity::error, "import-device", "--device: a module description file has no devices", document.path,
                                document.root_pos);
        return out;
    }
    finish(w, root, info);
    const std::string name = std::filesystem::path(document.path).filename().string();
    std::string text = "# Imported from " + (name.empty() ? std::string("an ESI file") : name) + " by esi-gen --import (docs/yaml-import.md)\n";
    text += root.render();
    out.yaml = std::move(text);
    return out;
}

}  // namespace esi
