#include "esi/codegen/generate.hpp"

#include <map>
#include <system_error>

#include "codegen/document_view.hpp"
#include "esi/codegen/mustache.hpp"
#include "esi/codegen/template_lookup.hpp"
#include "esi/io/same_file.hpp"
#include "esi/model/passive_terminal.hpp"
#include "esi/text_distance.hpp"

namespace esi::codegen {

namespace fs = std::filesystem;

namespace {

std::vector<const OutputKind*> selected_kinds(const GenerateOptions& options, const std::string& path, Diagnostics& diagnostics) {
    std::vector<const OutputKind*> kinds;
    if (options.only.empty()) {
        for (const auto& kind : output_kinds()) kinds.push_back(&kind);
        return kinds;
    }
    // Generated in the registry's order whatever order --only lists them in: deterministic.
    for (const auto& kind : output_kinds()) {
        for (const auto& wanted : options.only)
            if (wanted == kind.name) {
                kinds.push_back(&kind);
                break;
            }
    }
    Diagnostics unknown = check_output_kinds(options.only);
    for (auto& d : unknown.items()) {
        d.path = path;
        diagnostics.add(std::move(d));
    }
    return kinds;
}

std::string expand(const std::string& file_name, const std::string& stem) {
    std::string out = file_name;
    const std::string key = "{stem}";
    for (std::size_t at = out.find(key); at != std::string::npos; at = out.find(key, at + stem.size())) out.replace(at, key.size(), stem);
    return out;
}

std::string stem_of(const EsiDocument& document) {
    std::string stem = fs::path(document.path).stem().string();
    return stem.empty() ? "device" : stem;
}

struct Plan {
    std::vector<const OutputKind*> kinds;
    std::vector<DeviceViewEntry> devices;
    std::vector<PlannedFile> files;
    std::vector<const DeviceViewEntry*> file_devices;  // per file: its device, or null
    std::vector<const OutputArtifact*> file_artifacts;

    void add(PlannedFile file, const DeviceViewEntry* device, const OutputArtifact* artifact) {
        files.push_back(std::move(file));
        file_devices.push_back(device);
        file_artifacts.push_back(artifact);
    }
};

Plan make_plan(const EsiDocument& document, const GenerateOptions& options, Diagnostics& diagnostics) {
    Plan plan;
    plan.kinds = selected_kinds(options, document.path, diagnostics);
    plan.devices = selected_devices(document, options.view);
    if (diagnostics.has_errors()) return plan;
    bool any_device_kind = false;
    for (const auto* kind : plan.kinds) any_device_kind = any_device_kind || kind->scope == OutputScope::device;
    if (any_device_kind && plan.devices.empty()) {
        diagnostics.emplace(Severity::error, "codegen-no-device",
                            options.view.device ? "no device matches the --device selection" : "the source describes no device",
                            document.path, document.root_pos);
        return plan;
    }
    const std::string stem = stem_of(document);
    const bool subdirectories = plan.devices.size() > 1;
    // Document outputs first, then each device's outputs together (one mustache context each).
    for (const auto* kind : plan.kinds) {
        if (kind->scope != OutputScope::document) continue;
        for (const auto& artifact : kind->artifacts)
            plan.add({options.output_dir / expand(artifact.file_name, stem), kind->name, artifact.template_name}, nullptr, &artifact);
    }
    for (const auto& device : plan.devices) {
        const fs::path dir = subdirectories ? options.output_dir / device.c_name : options.output_dir;
        for (const auto* kind : plan.kinds) {
            if (kind->scope != OutputScope::device) continue;
            // A passive terminal has no ESC and so no EEPROM to program.
            if (kind->name == "sii" && device.device && is_passive_terminal(*device.device)) continue;
            for (const auto& artifact : kind->artifacts)
                plan.add({dir / expand(artifact.file_name, stem), kind->name, artifact.template_name}, &device, &artifact);
        }
    }
    // Writing over the source would destroy the input of the next run; so would an output
    // directory that is the source file itself (nothing could be written into it anyway).
    if (!document.path.empty()) {
        if (same_file(options.output_dir, document.path))
            diagnostics.emplace(Severity::error, "codegen-overwrites-source",
                                "the output directory " + options.output_dir.string() + " is the source file; choose another output directory",
                                document.path, {});
        for (const auto& file : plan.files) {
            if (same_file(file.path, document.path))
                diagnostics.emplace(Severity::error, "codegen-overwrites-source",
                                    "output " + file.path.string() + " is the source file itself; choose another output directory",
                                    document.path, {});
        }
    }
    return plan;
}

}  // namespace

Diagnostics check_output_kinds(const std::vector<std::string>& only) {
    Diagnostics diagnostics;
    std::vector<std::string_view> names;
    for (const auto& kind : output_kinds()) names.push_back(kind.name);
    for (const auto& wanted : only) {
        if (find_output_kind(wanted)) continue;
        std::string message = "unknown output kind '" + wanted + "'";
        const std::string suggestion = closest_match(wanted, names);
        if (!suggestion.empty()) message += " (did you mean '" + suggestion + "'?)";
        std::string all;
        for (const auto n : names) all += (all.empty() ? "" : ", ") + std::string(n);
        message += "; kinds: " + all;
        diagnostics.emplace(Severity::error, "codegen-unknown-kind", message, "", {});
    }
    return diagnostics;
}

std::vector<PlannedFile> plan_outputs(const EsiDocument& document, const GenerateOptions& options, Diagnostics& diagnostics) {
    Plan plan = make_plan(document, options, diagnostics);
    if (diagnostics.has_errors()) return {};
    return plan.files;
}

GenerateResult generate_outputs(const EsiDocument& document, const GenerateOptions& options) {
    GenerateResult result;
    Plan plan = make_plan(document, options, result.diagnostics);
    if (result.diagnostics.has_errors()) return result;

    // The view is built once; each template is parsed once and rendered for every device.
    DocumentView view;
    bool need_view = false;
    for (const auto& file : plan.files) need_view = need_view || !file.template_name.empty();
    if (need_view) {
        view = build_document_view(document, options.view);
        result.diagnostics.append(std::move(view.diagnostics));
        view.diagnostics = {};
    }

    struct LoadedTemplate {
        fs::path path;
        std::optional<mustache::Template> parsed;  // absent when it could not be read or parsed
        std::size_t last_size = 0;                  // output size of the previous rendering
    };
    std::map<std::string, LoadedTemplate> templates;
    auto load_template = [&](const std::string& name) -> LoadedTemplate* {
        if (auto it = templates.find(name); it != templates.end()) return it->second.parsed ? &it->second : nullptr;
        LoadedTemplate& loaded = templates[name];
        TemplateFile file = codegen::load_template(name, options.template_dirs, "codegen", result.diagnostics);
        loaded.path = std::move(file.path);
        loaded.parsed = std::move(file.parsed);
        return loaded.parsed ? &loaded : nullptr;
    };

    ViewValue context;
    const DeviceViewEntry* context_device = nullptr;
    for (std::size_t k = 0; k < plan.files.size(); ++k) {
        const PlannedFile& file = plan.files[k];
        const DeviceViewEntry* planned_device = plan.file_devices[k];
        const OutputArtifact* artifact = plan.file_artifacts[k];
        if (artifact->produce) {
            OutputFile out{file.path, {}};
            result.diagnostics.append(artifact->produce({document, planned_device ? planned_device->device : nullptr, options}, out.content));
            result.files.push_back(std::move(out));
            continue;
        }
        LoadedTemplate* tmpl = load_template(file.template_name);
        if (!tmpl) continue;
        const DeviceViewEntry* device = nullptr;
        for (const auto& d : view.devices)
            if (planned_device && d.device == planned_device->device) device = &d;
        if (!device) continue;
        if (device != context_device) {
            context = device_context(view, *device);
            context_device = device;
        }
        OutputFile out{file.path, {}};
        out.content.reserve(tmpl->last_size + tmpl->last_size / 8);
        tmpl->parsed->render(context, out.content);
        tmpl->last_size = out.content.size();
        result.files.push_back(std::move(out));
    }
    if (result.diagnostics.has_errors()) result.files.clear();
    return result;
}

}  // namespace esi::codegen
