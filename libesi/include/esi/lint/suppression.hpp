#pragma once
// Inline suppression in the XML itself:
//   <!-- esi-lint: disable=RULE[,RULE…] -->            from here to the end of the file (or an enable)
//   <!-- esi-lint: enable=RULE[,RULE…] -->             ends a disable
//   <!-- esi-lint: disable-next-line=RULE[,RULE…] -->  only the line after the comment
// "all" stands for every rule. xml-syntax cannot be suppressed (there is no document to trust).

#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/source_text.hpp"

namespace esi {

struct SuppressionRegion {
    std::string rule;  // rule id or "all"
    std::uint32_t first_line = 0;
    std::uint32_t last_line = 0;  // inclusive; UINT32_MAX for "to the end"
};

struct Suppressions {
    std::vector<SuppressionRegion> regions;
    [[nodiscard]] bool suppresses(const Diagnostic& diagnostic) const;
};

// Finds the directives in the text; malformed directives become lint-directive warnings.
[[nodiscard]] Suppressions find_suppressions(const SourceText& source, Diagnostics& diagnostics);

}  // namespace esi
