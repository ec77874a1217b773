#include "esi/enforce/limits.hpp"

#include "esi/check/registry.hpp"
#include "esi/check/run.hpp"
#include "esi/lint/config.hpp"

namespace esi {

namespace {

bool is_profile_rule(std::string_view id) { return id.starts_with("profile-"); }

// The document around one catalogue, without its devices: the rules see one device at a time,
// so that each is judged by its own limits even where two revisions of one product code declare
// different ones (EffectiveConfig scopes limits by product code only).
EsiDocument without_devices(const EsiDocument& document, const EtherCATInfo& info) {
    EsiDocument shell;
    shell.kind = document.kind;
    shell.path = document.path;
    shell.encoding = document.encoding;
    shell.source = document.source;
    shell.root_pos = document.root_pos;
    shell.infos.push_back(info);
    shell.infos.front().devices.clear();
    return shell;
}

}  // namespace

Diagnostics enforce_limits(const LoadedDocument& loaded, const LimitsOptions& options) {
    Diagnostics out;
    if (!loaded.document) return out;
    const EsiDocument& document = *loaded.document;

    EffectiveConfig profile;
    if (options.config) {
        ConfigResult read = load_lint_config(*options.config);
        const bool usable = read.config.has_value();
        out.append(std::move(read.diagnostics));
        if (!usable) return out;
        profile = effective_config(*read.config, document.path);
    }
    for (const Rule& rule : all_rules())
        if (!is_profile_rule(rule.id)) profile.rules[std::string(rule.id)] = RuleSetting::off;

    Diagnostics found;
    for (const EtherCATInfo& info : document.infos) {
        std::optional<EsiDocument> single;
        for (const Device& device : info.devices) {
            if (options.device && !options.device->matches(device)) continue;
            Limits limits = profile.limits_for(device.type.product_code);
            for (const auto& [selector, declared] : loaded.device_limits)
                if (selector.matches(device)) limits.merge(declared);
            if (limits.empty()) continue;
            if (!single) single = without_devices(document, info);
            single->infos.front().devices.assign(1, device);
            EffectiveConfig config;
            config.rules = profile.rules;
            config.limits = std::move(limits);
            found.append(run_rules(*single, config));
        }
    }
    found.sort();
    out.append(std::move(found));
    return out;
}

}  // namespace esi
