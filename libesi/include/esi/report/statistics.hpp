#pragma once
// `esi-lint --statistics`: how many findings each rule made, at which severity, instead of the
// findings themselves (ruff's --statistics): what a team adopting the linter on a catalogue looks
// at first, to decide which rules to switch off, re-grade or baseline.

#include <string>

#include "esi/lint/lint.hpp"

namespace esi {

// One line per (rule, severity), most frequent first, then by rule id:
//   "   12  warning  xml-hex-prefix  Hex number written with the C prefix 0x"
// followed by the summary line of the text format.
[[nodiscard]] std::string render_statistics_text(const LintReport& report);
// {"statistics":[{"rule","severity","count","summary"}],"summary":{…as render_json…}}
[[nodiscard]] std::string render_statistics_json(const LintReport& report);

}  // namespace esi
