#pragma once
// What the default severities mean. Every rule's default severity is set by this model, and the
// generated rule catalogue (docs/rules.md) opens with it.

#include <string_view>

namespace esi {

inline constexpr std::string_view severity_model =
    "Each rule has one default severity, set by what a real master does with the finding:\n"
    "\n"
    "- **error**: a master, the SII builder or the ETG conformance test tool misreads or rejects the device: a wrong\n"
    "  process-image layout, a SyncManager or FMMU conflict, an identity that cannot be matched, a start-up command\n"
    "  the device refuses, a value outside what the schema allows. `esi-lint --fail-on error` fails on these.\n"
    "- **warning**: inconsistent or deprecated, but tolerated by masters: offline Dictionary layouts and defaults\n"
    "  (masters read objects one sub-index at a time, lay out process data by the PDO entries and identify a device\n"
    "  by its SII), stale copies of what the device reports itself, vendor spellings, indices that are only labels.\n"
    "- **info**: style.\n"
    "\n"
    "Where one fault has a case masters trip on and a case they tolerate, these are two rules with their own\n"
    "severities (pdo-index-range and pdo-index-area, od-mandatory-object and od-mandatory-object-offline). A rule\n"
    "that is a warning although its fault sounds grave says in its rationale why masters tolerate it. The verdicts\n"
    "on the vendors' own catalogues are reviewed in corpus-review.md.\n";

}  // namespace esi
