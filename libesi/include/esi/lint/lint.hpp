#pragma once
// The esi-lint pipeline as a library call: read, run the rules the config enables, apply
// severities and inline suppressions. Files are linted in parallel; results come back in a
// deterministic order.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "esi/check/registry.hpp"
#include "esi/check/run.hpp"
#include "esi/diagnostic.hpp"
#include "esi/lint/config.hpp"
#include "esi/source_text.hpp"
#include "esi/xml/reader.hpp"

namespace esi {

struct LintOptions {
    // Used for every file instead of the nearest .esi-lint.yaml.
    std::optional<std::filesystem::path> config_path;
    // Also validate against the ETG schema files in this directory (libxml2).
    std::optional<std::filesystem::path> xsd_dir;
    unsigned jobs = 0;  // 0: all cores
};

struct FileReport {
    std::string path;
    Diagnostics diagnostics;  // sorted
    // The source lines the diagnostics point at (line number -> text), kept so reports can quote
    // them without holding every file's text in memory.
    std::map<std::uint32_t, std::string> quoted_lines;
    bool unreadable = false;  // io-error: the file could not be read at all
};

struct LintReport {
    std::vector<FileReport> files;  // in the order the inputs were given (directories sorted)
    Diagnostics config_diagnostics;  // problems in .esi-lint.yaml files
    [[nodiscard]] std::size_t count(Severity severity) const;
    [[nodiscard]] bool any_unreadable() const;
};

// Lints bytes (for stdin or tests) under a given config.
[[nodiscard]] FileReport lint_bytes(std::string_view bytes, const std::string& path, const EffectiveConfig& config,
                                    const std::optional<std::filesystem::path>& xsd_dir = std::nullopt);

// Expands directories (recursive *.xml, sorted) and lints every file.
[[nodiscard]] LintReport lint_paths(const std::vector<std::filesystem::path>& inputs, const LintOptions& options);

// The files lint_paths would read, in order; problems (missing inputs) go to `diagnostics`.
[[nodiscard]] std::vector<std::filesystem::path> expand_inputs(const std::vector<std::filesystem::path>& inputs,
                                                                Diagnostics& diagnostics);

}  // namespace esi
