#pragma once
// esi-lint's report as SARIF 2.1.0 (OASIS), shaped for GitHub code scanning and the SARIF
// multitool's validation rules:
//  - artifact URIs are relative to %SRCROOT% (`originalUriBaseIds` gives its absolute file: URI),
//    so alerts land on the repository's files wherever the checkout was; a file outside the
//    root gets an absolute file: URI;
//  - a file that could not be read and a broken config are tool execution notifications of the
//    invocation (executionSuccessful false), not results: they are not defects in the files;
//  - each result has a partialFingerprints entry computed from the rule id, the file and the
//    whitespace-normalised text of its line, so an alert survives lines added above it;
//  - each rule has a helpUri into docs/rules.md when the docs' published address is known.

#include <filesystem>
#include <string>

#include "esi/lint/lint.hpp"

namespace esi {

struct SarifOptions {
    std::string tool_version;
    // %SRCROOT%, absolute: the directory relative URIs are resolved against (esi-lint: the
    // current directory, where CI runs it from the checkout's root).
    std::filesystem::path source_root;
    // The absolute URL of docs/rules.md as published (e.g. the repository's page of it); each
    // rule's helpUri is this with the rule id as fragment (the heading anchor). Empty: no helpUri,
    // the rule's help text carries the rationale and examples.
    std::string rules_url;
};

// The key of the fingerprint in partialFingerprints.
inline constexpr std::string_view sarif_fingerprint_key = "esiLint/v1";

[[nodiscard]] std::string render_sarif(const LintReport& report, const SarifOptions& options);

}  // namespace esi
