#pragma once
// .esi-lint.yaml: which rules run at which severity, the vendor's own limits, per-file overrides.
//
//   extends: [profiles/servo.yaml]      # relative to this file; later entries win
//   rules: { sm-size-zero: off, pdo-entry-bitlen: error }
//   limits: { max_pdos: {rx: 4, tx: 4}, max_entries_per_pdo: 6, bitlen: [8, 16, 32] }
//   exclude: ["vendor/*", "*.eni.xml"]   # files a directory walk does not lint
//   overrides:
//     - files: ["legacy/*.xml"]          # globs against the path relative to this file
//       product_codes: [0x264860d2]      # optional: limits apply to these devices only
//       rules: { … }
//       limits: { … }

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "esi/check/effective_config.hpp"
#include "esi/diagnostic.hpp"

namespace esi {

struct ConfigOverride {
    std::vector<std::string> files;  // globs; empty: every file
    std::vector<std::uint32_t> product_codes;
    std::map<std::string, RuleSetting, std::less<>> rules;
    Limits limits;
};

// A glob and the directory it is relative to (the config file that states it: an extended
// profile's globs stay relative to the profile).
struct ExcludeGlob {
    std::filesystem::path base;
    std::string glob;
};

struct LintConfig {
    std::filesystem::path path;  // where it was read from; empty for the built-in default
    std::map<std::string, RuleSetting, std::less<>> rules;
    Limits limits;
    std::vector<ConfigOverride> overrides;
    std::vector<ExcludeGlob> exclude;
};

struct ConfigResult {
    std::optional<LintConfig> config;
    Diagnostics diagnostics;  // with the config file's path and positions
};

// Reads a config file (and what it extends). Errors are diagnostics; unknown keys and rule ids
// get a did-you-mean.
[[nodiscard]] ConfigResult load_lint_config(const std::filesystem::path& path);

// The nearest .esi-lint.yaml in the file's directory or above; nullopt when there is none.
[[nodiscard]] std::optional<std::filesystem::path> find_config_for(const std::filesystem::path& file);

// Whether a glob (the syntax of `files:` in overrides) matches the file or one of the directories
// it lies in, with paths relative to `base`: `legacy` and `legacy/*` both exclude legacy/a.xml and
// legacy/old/b.xml; a glob without '/' matches a name anywhere, as in .gitignore.
[[nodiscard]] bool exclude_matches(const ExcludeGlob& exclude, const std::filesystem::path& file);

[[nodiscard]] EffectiveConfig effective_config(const LintConfig& config, const std::filesystem::path& file);

}  // namespace esi
