#include "esi/codegen/generate.hpp"

#include <map>
#include <system_error>

#include "codegen/document_view.hpp"
#include "codegen/mustache_context.hpp"
#include "esi/codegen/template_lookup.hpp"
#include "esi/text_distance.hpp"
#include "esi/xml/reader.hpp"

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
            for (const auto& artifact : kind->artifacts)
                plan.add({dir / expand(artifact.file_name, stem), kind->name, artifact.template_name}, &device, &artifact);
        }
    }
    // Writing over the source would destroy the input of the next run.
    std::error_code ec;
    for (const auto& file : plan.files) {
        if (!document.path.empty() && fs::exists(file.path, ec) && fs::equivalent(file.path, document.path, ec)) {
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

    // The view is built once; each device's mustache data once for all its templates.
    DocumentView view;
    bool need_view = false;
    for (const auto& file : plan.files) need_view = need_view || !file.template_name.empty();
    if (need_view) {
        view = build_document_view(document, options.view);
        result.diagnostics.append(std::move(view.diagnostics));
        view.diagnostics = {};
    }

    std::map<std::string, std::pair<fs::path, std::string>> templates;  // name -> (path, text)
    auto load_template = [&](const std::string& name) -> const std::pair<fs::path, std::string>* {
        if (auto it = templates.find(name); it != templates.end()) return &it->second;
        const auto path = find_template(name, options.template_dirs);
        if (!path) {
            std::string searched;
            for (const auto& d : options.template_dirs) searched += (searched.empty() ? "" : ", ") + d.string();
            result.diagnostics.emplace(Severity::error, "codegen-template-missing",
                                       "template '" + name + "' not found (searched: " + (searched.empty() ? "nothing" : searched) + ")",
                                       "", {});
            return nullptr;
        }
        std::string error;
        auto text = read_file_bytes(*path, error);
        if (!text) {
            result.diagnostics.emplace(Severity::error, "io-error", error, path->string(), {});
            return nullptr;
        }
        return &templates.emplace(name, std::make_pair(*path, std::move(*text))).first->second;
    };

    std::unique_ptr<MustacheContext> context;
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
        const auto* tmpl = load_template(file.template_name);
        if (!tmpl) continue;
        DeviceViewEntry* device = nullptr;
        for (auto& d : view.devices)
            if (planned_device && d.device == planned_device->device) device = &d;
        if (!device) continue;
        if (device != context_device) {
            // Each device's view is used once: it moves into its context instead of being copied.
            context = std::make_unique<MustacheContext>(device_context(view, std::move(*device)));
            context_device = device;
        }
        Rendered rendered = context->render(tmpl->second);
        if (!rendered.ok) {
            result.diagnostics.emplace(Severity::error, "codegen-template-error", rendered.error, tmpl->first.string(), rendered.pos);
            continue;
        }
        result.files.push_back({file.path, std::move(rendered.text)});
    }
    if (result.diagnostics.has_errors()) result.files.clear();
    return result;
}

}  // namespace esi::codegen
