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
    // Globs (relative to the current directory) of files a directory walk does not lint, added to
    // the `exclude:` of each file's config (esi/lint/config.hpp).
    std::vector<std::string> exclude;
};

struct FileReport {
    std::string path;
    Diagnostics diagnostics;  // sorted
    // The source lines the diagnostics point at (line number -> text), kept so reports can quote
    // them without holding every file's text in memory.
    std::map<std::uint32_t, std::string> quoted_lines;
    // Where the fixes' edits begin and end (offset into the decoded text -> line and column), for
    // reports that address text by position (SARIF's deletedRegion).
    std::map<std::size_t, SourcePos> fix_positions;
    bool unreadable = false;  // io-error: the file could not be read at all
    // Not linted, and why: an XML file found by a directory walk that is not an ESI file (an
    // ENI, a master's configuration; esi/xml/foreign_root.hpp). Named files are never skipped.
    std::string skipped;
};

struct LintReport {
    std::vector<FileReport> files;  // in the order the inputs were given (directories sorted)
    Diagnostics config_diagnostics;  // problems in .esi-lint.yaml files
    // A config file had an error: no file was linted (files holds only the inputs that were
    // missing), rather than linting under a config the user did not write.
    bool stopped_by_config = false;
    std::size_t excluded = 0;  // files a directory walk found that an exclude glob left out
    std::size_t baselined = 0;  // findings left out because the baseline holds them (esi/report/baseline.hpp)
    [[nodiscard]] std::size_t count(Severity severity) const;
    [[nodiscard]] bool any_unreadable() const;
};

// Lints bytes (for stdin or tests) under a given config. An ESI file (XML) or a YAML device source,
// told apart by content (esi/load/document.hpp); a YAML source is linted on the model it
// describes, with positions in the YAML.
[[nodiscard]] FileReport lint_bytes(std::string_view bytes, const std::string& path, const EffectiveConfig& config,
                                    const std::optional<std::filesystem::path>& xsd_dir = std::nullopt);
// The same, taking the bytes over: an ESI file is read from them in place, without a copy.
[[nodiscard]] FileReport lint_bytes(std::string&& bytes, const std::string& path, const EffectiveConfig& config,
                                    const std::optional<std::filesystem::path>& xsd_dir = std::nullopt);

// Expands directories (recursive *.xml, sorted) and lints every file. A named file ending in
// .yaml/.yml is a YAML device source; directory walks take only *.xml (a repository's YAML files
// are mostly other things: CI jobs, .esi-lint.yaml itself, master configurations).
[[nodiscard]] LintReport lint_paths(const std::vector<std::filesystem::path>& inputs, const LintOptions& options);

// The files lint_paths would read, in order; problems (missing inputs) go to `diagnostics`.
[[nodiscard]] std::vector<std::filesystem::path> expand_inputs(const std::vector<std::filesystem::path>& inputs,
                                                                Diagnostics& diagnostics);

}  // namespace esi
