#include "esi/lint/config.hpp"

#include <algorithm>
#include <fnmatch.h>
#include <set>

#include "esi/check/registry.hpp"
#include "esi/number.hpp"
#include "esi/text_distance.hpp"
#include "esi/xml/reader.hpp"

namespace esi {

namespace {

SourcePos mark_of(const YAML::Node& node) {
    const YAML::Mark mark = node.Mark();
    if (mark.line < 0) return {};
    return SourcePos{static_cast<std::uint32_t>(mark.line + 1), static_cast<std::uint32_t>(mark.column + 1)};
}

class ConfigParser {
public:
    ConfigParser(std::string path, Diagnostics& diagnostics) : path_(std::move(path)), diagnostics_(diagnostics) {}

    void error(const YAML::Node& at, std::string message) {
        diagnostics_.emplace(Severity::error, "config", std::move(message), path_, mark_of(at));
    }

    void check_keys(const YAML::Node& map, std::span<const std::string_view> allowed, std::string_view where) {
        for (const auto& kv : map) {
            const std::string key = kv.first.as<std::string>("");
            if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
            std::string message = "unknown key '" + key + "' in " + std::string(where);
            if (const std::string suggestion = closest_match(key, allowed); !suggestion.empty())
                message += "; did you mean '" + suggestion + "'?";
            error(kv.first, message);
        }
    }

    std::optional<std::uint32_t> u32(const YAML::Node& node, std::string_view what) {
        if (!node.IsScalar()) {
            error(node, std::string(what) + " must be a number");
            return std::nullopt;
        }
        const ParsedNumber n = parse_number(node.Scalar());
        if (!n.ok() || n.value.negative || n.value.magnitude > 0xFFFFFFFFu) {
            error(node, std::string(what) + ": '" + node.Scalar() + "' is not a number from 0 to 0xFFFFFFFF");
            return std::nullopt;
        }
        return static_cast<std::uint32_t>(n.value.magnitude);
    }

    std::vector<IndexRange> ranges(const YAML::Node& node, std::string_view what) {
        std::vector<IndexRange> out;
        if (!node.IsSequence()) {
            error(node, std::string(what) + " must be a list of ranges such as [0x1600, 0x1603] or \"0x1600-0x1603\"");
            return out;
        }
        for (const auto& item : node) {
            if (item.IsSequence() && item.size() == 2) {
                auto first = u32(item[0], what);
                auto last = u32(item[1], what);
                if (first && last) out.push_back({*first, *last});
            } else if (item.IsScalar()) {
                const std::string s = item.Scalar();
                const auto dash = s.find_first_of("-", 1);
                const auto dots = s.find("..");
                if (dash != std::string::npos || dots != std::string::npos) {
                    const std::size_t cut = dots != std::string::npos ? dots : dash;
                    const std::size_t skip = dots != std::string::npos ? 2 : 1;
                    const ParsedNumber a = parse_number(s.substr(0, cut));
                    const ParsedNumber b = parse_number(s.substr(cut + skip));
                    if (a.ok() && b.ok() && a.value.magnitude <= 0xFFFFFFFFu && b.value.magnitude <= 0xFFFFFFFFu)
                        out.push_back({static_cast<std::uint32_t>(a.value.magnitude), static_cast<std::uint32_t>(b.value.magnitude)});
                    else
                        error(item, std::string(what) + ": '" + s + "' is not a range");
                } else if (auto v = u32(item, what)) {
                    out.push_back({*v, *v});
                }
            } else {
                error(item, std::string(what) + ": each range is [first, last] or \"first-last\"");
            }
        }
        for (const auto& r : out)
            if (r.first > r.last) error(node, std::string(what) + ": a range ends before it starts");
        return out;
    }

    Limits limits(const YAML::Node& node) {
        Limits l;
        if (!node.IsMap()) {
            error(node, "limits must be a mapping");
            return l;
        }
        static constexpr std::string_view keys[] = {"max_pdos", "pdo_index_ranges", "max_entries_per_pdo", "bitlen", "fixed_sm",
                                                    "transitions", "max_init_cmd_bytes", "max_mailbox_size", "absent_objects"};
        check_keys(node, keys, "limits");
        if (const auto n = node["max_pdos"]) {
            if (n.IsMap()) {
                static constexpr std::string_view dir_keys[] = {"rx", "tx"};
                check_keys(n, dir_keys, "max_pdos");
                if (n["rx"]) l.max_rx_pdos = u32(n["rx"], "max_pdos.rx");
                if (n["tx"]) l.max_tx_pdos = u32(n["tx"], "max_pdos.tx");
            } else if (auto v = u32(n, "max_pdos")) {
                l.max_rx_pdos = l.max_tx_pdos = v;
            }
        }
        if (const auto n = node["pdo_index_ranges"]) {
            if (!n.IsMap()) error(n, "pdo_index_ranges must be a mapping with rx and tx");
            else {
                static constexpr std::string_view dir_keys[] = {"rx", "tx"};
                check_keys(n, dir_keys, "pdo_index_ranges");
                if (n["rx"]) l.rx_pdo_ranges = ranges(n["rx"], "pdo_index_ranges.rx");
                if (n["tx"]) l.tx_pdo_ranges = ranges(n["tx"], "pdo_index_ranges.tx");
            }
        }
        if (const auto n = node["max_entries_per_pdo"]) l.max_entries_per_pdo = u32(n, "max_entries_per_pdo");
        if (const auto n = node["bitlen"]) {
            if (!n.IsSequence()) error(n, "bitlen must be a list of allowed BitLen values");
            else
                for (const auto& v : n)
                    if (auto b = u32(v, "bitlen")) l.allowed_bit_lens.push_back(*b);
        }
        if (const auto n = node["fixed_sm"]) {
            if (!n.IsMap()) error(n, "fixed_sm must map SM numbers to MBoxOut, MBoxIn, Outputs or Inputs");
            else
                for (const auto& kv : n) {
                    auto sm = u32(kv.first, "fixed_sm");
                    const std::string type = kv.second.as<std::string>("");
                    if (type != "MBoxOut" && type != "MBoxIn" && type != "Outputs" && type != "Inputs") {
                        error(kv.second, "fixed_sm: '" + type + "' is not MBoxOut, MBoxIn, Outputs or Inputs");
                        continue;
                    }
                    if (sm) l.fixed_sms[*sm] = type;
                }
        }
        if (const auto n = node["transitions"]) {
            if (!n.IsSequence()) error(n, "transitions must be a list such as [IP, PS, SO]");
            else
                for (const auto& v : n) l.allowed_transitions.push_back(v.as<std::string>(""));
        }
        if (const auto n = node["max_init_cmd_bytes"]) l.max_init_cmd_bytes = u32(n, "max_init_cmd_bytes");
        if (const auto n = node["max_mailbox_size"]) l.max_mailbox_size = u32(n, "max_mailbox_size");
        if (const auto n = node["absent_objects"]) {
            if (!n.IsSequence()) error(n, "absent_objects must be a list of object indices");
            else
                for (const auto& v : n)
                    if (auto i = u32(v, "absent_objects")) l.absent_objects.push_back(*i);
        }
        return l;
    }

    std::map<std::string, RuleSetting, std::less<>> rules(const YAML::Node& node) {
        std::map<std::string, RuleSetting, std::less<>> out;
        if (!node.IsMap()) {
            error(node, "rules must map rule ids to off, info, warning or error");
            return out;
        }
        std::vector<std::string_view> ids;
        for (const auto& r : all_rules()) ids.push_back(r.id);
        for (const auto& kv : node) {
            const std::string id = kv.first.as<std::string>("");
            if (!find_rule(id)) {
                std::string message = "unknown rule '" + id + "'";
                if (const std::string s = closest_match(id, ids); !s.empty()) message += "; did you mean '" + s + "'?";
                error(kv.first, message);
                continue;
            }
            const std::string value = kv.second.IsScalar() ? kv.second.Scalar() : "";
            if (value == "off" || value == "false") out[id] = RuleSetting::off;
            else if (value == "info") out[id] = RuleSetting::info;
            else if (value == "warning") out[id] = RuleSetting::warning;
            else if (value == "error") out[id] = RuleSetting::error;
            else error(kv.second, "rule '" + id + "': '" + value + "' is not off, info, warning or error");
        }
        return out;
    }

    std::vector<std::string> strings(const YAML::Node& node, std::string_view what) {
        std::vector<std::string> out;
        if (node.IsScalar()) out.push_back(node.Scalar());
        else if (node.IsSequence())
            for (const auto& v : node) out.push_back(v.as<std::string>(""));
        else error(node, std::string(what) + " must be a string or a list of strings");
        return out;
    }

private:
    std::string path_;
    Diagnostics& diagnostics_;
};

void load_into(const std::filesystem::path& path, LintConfig& config, Diagnostics& diagnostics,
               std::set<std::filesystem::path>& visiting) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    if (visiting.count(canonical)) {
        diagnostics.emplace(Severity::error, "config", "extends cycle through " + path.string(), path.string(), {});
        return;
    }
    visiting.insert(canonical);
    std::string io_error;
    const std::optional<std::string> bytes = read_file_bytes(path, io_error);
    if (!bytes) {
        diagnostics.emplace(Severity::error, "config", "cannot read config: " + io_error, path.string(), {});
        return;
    }
    YAML::Node root;
    try {
        root = YAML::Load(*bytes);
    } catch (const YAML::Exception& e) {
        diagnostics.emplace(Severity::error, "config", "YAML syntax: " + e.msg, path.string(),
                            SourcePos{static_cast<std::uint32_t>(e.mark.line + 1), static_cast<std::uint32_t>(e.mark.column + 1)});
        return;
    }
    if (root.IsNull()) return;
    ConfigParser parser(path.string(), diagnostics);
    if (!root.IsMap()) {
        parser.error(root, "the config must be a mapping with extends, rules, limits and overrides");
        return;
    }
    static constexpr std::string_view keys[] = {"extends", "rules", "limits", "overrides"};
    parser.check_keys(root, keys, "the config");
    if (const auto n = root["extends"]) {
        for (const std::string& base : parser.strings(n, "extends")) {
            const std::filesystem::path base_path = path.parent_path() / base;
            load_into(base_path, config, diagnostics, visiting);
        }
    }
    if (const auto n = root["rules"])
        for (const auto& [id, setting] : parser.rules(n)) config.rules[id] = setting;
    if (const auto n = root["limits"]) config.limits.merge(parser.limits(n));
    if (const auto n = root["overrides"]) {
        if (!n.IsSequence()) parser.error(n, "overrides must be a list");
        else
            for (const auto& item : n) {
                if (!item.IsMap()) {
                    parser.error(item, "each override is a mapping with files, product_codes, rules and limits");
                    continue;
                }
                static constexpr std::string_view override_keys[] = {"files", "product_codes", "rules", "limits"};
                parser.check_keys(item, override_keys, "an override");
                ConfigOverride o;
                if (item["files"]) o.files = parser.strings(item["files"], "files");
                if (const auto pc = item["product_codes"]) {
                    if (pc.IsSequence()) {
                        for (const auto& v : pc)
                            if (auto code = parser.u32(v, "product_codes")) o.product_codes.push_back(*code);
                    } else if (auto code = parser.u32(pc, "product_codes")) {
                        o.product_codes.push_back(*code);
                    }
                }
                if (item["rules"]) o.rules = parser.rules(item["rules"]);
                if (item["limits"]) o.limits = parser.limits(item["limits"]);
                config.overrides.push_back(std::move(o));
            }
    }
    visiting.erase(canonical);
}

bool glob_matches(const std::string& pattern, const std::filesystem::path& relative) {
    const std::string text = relative.generic_string();
    if (fnmatch(pattern.c_str(), text.c_str(), FNM_PATHNAME) == 0) return true;
    // A pattern without '/' matches the file name anywhere, as .gitignore does.
    if (pattern.find('/') == std::string::npos)
        return fnmatch(pattern.c_str(), relative.filename().c_str(), 0) == 0;
    return false;
}

}  // namespace

ConfigResult load_lint_config(const std::filesystem::path& path) {
    ConfigResult result;
    LintConfig config;
    config.path = path;
    std::set<std::filesystem::path> visiting;
    load_into(path, config, result.diagnostics, visiting);
    result.diagnostics.sort();
    if (!result.diagnostics.has_errors()) result.config = std::move(config);
    return result;
}

Limits parse_limits(const YAML::Node& node, const std::string& path, Diagnostics& diagnostics) {
    ConfigParser parser(path, diagnostics);
    return parser.limits(node);
}

std::optional<std::filesystem::path> find_config_for(const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::path dir = std::filesystem::absolute(file, ec).parent_path();
    while (!dir.empty()) {
        const std::filesystem::path candidate = dir / ".esi-lint.yaml";
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
        if (dir == dir.root_path()) break;
        dir = dir.parent_path();
    }
    return std::nullopt;
}

const Limits& EffectiveConfig::limits_for(std::optional<std::uint32_t> product_code) const {
    if (product_code)
        for (const auto& [codes, device_limits_entry] : device_limits)
            if (std::find(codes.begin(), codes.end(), *product_code) != codes.end()) return device_limits_entry;
    return limits;
}

std::optional<Severity> EffectiveConfig::severity_of(std::string_view rule_id, Severity default_severity) const {
    const auto it = rules.find(rule_id);
    if (it == rules.end()) return default_severity;
    switch (it->second) {
        case RuleSetting::off: return std::nullopt;
        case RuleSetting::info: return Severity::info;
        case RuleSetting::warning: return Severity::warning;
        case RuleSetting::error: return Severity::error;
    }
    return default_severity;
}

EffectiveConfig effective_config(const LintConfig& config, const std::filesystem::path& file) {
    EffectiveConfig out;
    out.rules = config.rules;
    out.limits = config.limits;
    std::error_code ec;
    std::filesystem::path relative = file;
    if (!config.path.empty()) {
        const auto base = std::filesystem::absolute(config.path, ec).parent_path();
        relative = std::filesystem::absolute(file, ec).lexically_relative(base);
    }
    for (const auto& o : config.overrides) {
        const bool file_matches = o.files.empty() || std::any_of(o.files.begin(), o.files.end(), [&](const std::string& g) {
                                      return glob_matches(g, relative);
                                  });
        if (!file_matches) continue;
        for (const auto& [id, setting] : o.rules) out.rules[id] = setting;
        if (o.product_codes.empty()) {
            out.limits.merge(o.limits);
        } else {
            Limits device = out.limits;
            device.merge(o.limits);
            out.device_limits.emplace_back(o.product_codes, std::move(device));
        }
    }
    return out;
}

}  // namespace esi
