#include "esi/lint/config.hpp"

#include <algorithm>
#include <fnmatch.h>
#include <set>

#include "esi/check/registry.hpp"
#include "esi/yaml/limits.hpp"
#include "esi/yaml/reader.hpp"
#include "esi/yaml/tree.hpp"
#include "esi/io/read_file.hpp"

namespace esi {

namespace {

using yaml::Fields;
using yaml::Node;

// Reads one config file's mapping; `extends` is followed by load_into.
class ConfigParser {
public:
    ConfigParser(const std::string& path, Diagnostics& diagnostics) : reader_(path, diagnostics) {}

    yaml::Reader& reader() { return reader_; }

    std::map<std::string, RuleSetting, std::less<>> rules(const Node& node) {
        std::map<std::string, RuleSetting, std::less<>> out;
        if (!node.IsMap()) {
            reader_.error(node, "yaml-type", "'rules' must map rule ids to off, info, warning or error");
            return out;
        }
        std::vector<std::string_view> ids;
        for (const auto& r : all_rules()) ids.push_back(r.id);
        const Fields fields(node);
        for (const auto& item : fields.items()) {
            const std::string id(item.key);
            if (!find_rule(id)) {
                reader_.error(item.key_node, "yaml-unknown-key", "unknown rule '" + id + "'" + yaml::did_you_mean(id, ids));
                continue;
            }
            const std::string value = item.value.IsScalar() ? item.value.Scalar() : "";
            if (value == "off" || value == "false") out[id] = RuleSetting::off;
            else if (value == "info") out[id] = RuleSetting::info;
            else if (value == "warning") out[id] = RuleSetting::warning;
            else if (value == "error") out[id] = RuleSetting::error;
            else reader_.error(item.value, "yaml-type", "rule '" + id + "': '" + value + "' is not off, info, warning or error");
        }
        return out;
    }

    // One string or a list of strings.
    std::vector<std::string> strings(const Node& node, std::string_view what) {
        std::vector<std::string> out;
        if (node.IsScalar()) {
            out.push_back(node.Scalar());
        } else if (const auto items = reader_.sequence(node, what)) {
            for (const Node& item : *items)
                if (const auto text = reader_.text(item, what)) out.push_back(*text);
        }
        return out;
    }

    std::vector<std::uint32_t> product_codes(const Node& node) {
        std::vector<std::uint32_t> out;
        if (node.IsSequence()) {
            for (const Node& item : node)
                if (const auto code = reader_.integer<std::uint32_t>(item, "product_codes")) out.push_back(*code);
        } else if (const auto code = reader_.integer<std::uint32_t>(node, "product_codes")) {
            out.push_back(*code);
        }
        return out;
    }

private:
    yaml::Reader reader_;
};

void load_into(const std::filesystem::path& path, LintConfig& config, Diagnostics& diagnostics,
               std::set<std::filesystem::path>& visiting);

// One file's settings merged into `config`; `visiting` holds the files whose `extends` are being
// followed (a file extended twice along different paths is not a cycle).
void read_config_file(const std::filesystem::path& path, LintConfig& config, Diagnostics& diagnostics,
                      std::set<std::filesystem::path>& visiting) {
    std::string io_error;
    const std::optional<std::string> bytes = read_file_bytes(path, io_error);
    if (!bytes) {
        diagnostics.emplace(Severity::error, "config", "cannot read config: " + io_error, path.string(), {});
        return;
    }
    bool empty = false;
    const std::unique_ptr<yaml::Tree> tree = yaml::Tree::parse(*bytes, path.string(), yaml::TreeLimits{}, diagnostics, empty);
    // A syntax error has been reported; an empty file configures nothing.
    if (!tree || tree->root()->kind == yaml::TreeNode::Kind::null) return;
    ConfigParser parser(path.string(), diagnostics);
    static constexpr std::string_view keys[] = {"extends", "rules", "limits", "overrides", "exclude"};
    const auto root = parser.reader().mapping(Node(tree->root()), keys, "the config");
    if (!root) return;
    if (const Node* n = root->find("extends")) {
        for (const std::string& base : parser.strings(*n, "extends")) {
            const std::filesystem::path base_path = path.parent_path() / base;
            load_into(base_path, config, diagnostics, visiting);
        }
    }
    if (const Node* n = root->find("rules"))
        for (const auto& [id, setting] : parser.rules(*n)) config.rules[id] = setting;
    if (const Node* n = root->find("limits")) config.limits.merge(yaml::read_limits(parser.reader(), *n));
    if (const Node* n = root->find("exclude")) {
        std::error_code ec;
        const std::filesystem::path base = std::filesystem::absolute(path, ec).parent_path();
        for (std::string& glob : parser.strings(*n, "exclude")) config.exclude.push_back({base, std::move(glob)});
    }
    if (const Node* n = root->find("overrides")) {
        static constexpr std::string_view override_keys[] = {"files", "product_codes", "rules", "limits"};
        if (const auto items = parser.reader().sequence(*n, "overrides")) {
            for (const Node& item : *items) {
                const auto f = parser.reader().mapping(item, override_keys, "an override");
                if (!f) continue;
                ConfigOverride o;
                if (const Node* v = f->find("files")) o.files = parser.strings(*v, "files");
                if (const Node* v = f->find("product_codes")) o.product_codes = parser.product_codes(*v);
                if (const Node* v = f->find("rules")) o.rules = parser.rules(*v);
                if (const Node* v = f->find("limits")) o.limits = yaml::read_limits(parser.reader(), *v);
                config.overrides.push_back(std::move(o));
            }
        }
    }
}

void load_into(const std::filesystem::path& path, LintConfig& config, Diagnostics& diagnostics,
               std::set<std::filesystem::path>& visiting) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    if (visiting.count(canonical)) {
        diagnostics.emplace(Severity::error, "config", "extends cycle through " + path.string(), path.string(), {});
        return;
    }
    visiting.insert(canonical);
    read_config_file(path, config, diagnostics, visiting);
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

bool exclude_matches(const ExcludeGlob& exclude, const std::filesystem::path& file) {
    std::error_code ec;
    const std::filesystem::path relative =
        std::filesystem::absolute(file, ec).lexically_normal().lexically_relative(exclude.base.lexically_normal());
    if (relative.empty() || *relative.begin() == "..") return false;
    std::string glob = exclude.glob;
    while (glob.size() > 1 && glob.back() == '/') glob.pop_back();  // "legacy/" names the directory
    if (glob.starts_with("./")) glob.erase(0, 2);
    std::filesystem::path prefix;
    for (const auto& part : relative) {
        prefix /= part;
        if (glob_matches(glob, prefix)) return true;
    }
    return false;
}

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
