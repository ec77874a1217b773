#pragma once
// esi-lint --fix and --diff: applying the safe fixes the rules attach to their findings
// (Diagnostic::fix, esi/diagnostic.hpp) to a file as it is stored.
//
// A fix's edits address the decoded UTF-8 text; here they are mapped back to the file's bytes
// (UTF-8 with or without a byte-order mark: the same offsets, shifted by the mark; ISO-8859-1 and
// Windows-1252: one byte per character), and only those bytes change: the encoding, the line
// endings, the comments and everything else stay byte-identical. Edits that overlap an earlier
// one are left for the next run. Before anything is written the fixed text is linted again: a
// fix that leaves its finding, or makes a finding that was not there, refuses the whole file.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/check/effective_config.hpp"
#include "esi/diagnostic.hpp"
#include "esi/lint/lint.hpp"

namespace esi {

struct FixedText {
    std::string original;           // the file as it was read
    std::string bytes;              // the file with the fixes applied
    std::vector<TextEdit> edits;    // what was applied, as offsets into the original bytes, in order
    std::size_t applied = 0;        // findings fixed
    std::string refused;            // non-empty: nothing applied (bytes is the original), and why
};

// Lints `original` (the file's bytes) under `config`, applies the fixes of its findings (those the
// config enables and no inline suppression hides) and checks the outcome by linting it again.
[[nodiscard]] FixedText apply_fixes(std::string_view original, const std::string& path, const EffectiveConfig& config);

// apply_fixes for a file on disk, under the config lint_paths would use for it (options.config_path
// or the nearest .esi-lint.yaml). A file that cannot be read, or whose config has an error, is
// refused with the reason.
[[nodiscard]] FixedText fix_file(const std::filesystem::path& path, const LintOptions& options);

// Replaces the file with the fixed bytes (atomically, keeping its permissions); io-error
// diagnostics when it cannot.
[[nodiscard]] Diagnostics write_fixed_file(const std::filesystem::path& path, const FixedText& fixed);

// The unified diff (diff -u, three lines of context) of `original` and the result of `edits`
// (non-overlapping, in order, offsets into `original`), both shown under `path` (a/…, b/…).
// Built from the edits, so a catalogue of a million lines costs the lines around them.
[[nodiscard]] std::string unified_diff(std::string_view original, const std::vector<TextEdit>& edits, const std::string& path);

}  // namespace esi
