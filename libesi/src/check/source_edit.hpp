#pragma once
// Safe fixes that rewrite an element's text: the rules know the element's position in the model;
// the fix needs the bytes, found in the document's source text and checked to be what the model
// read, so that a fix is never applied to text that differs from what the rule saw.

#include <optional>
#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::rules {

// Replaces the character data of the element starting at `element` (the '<' of its start tag)
// when it is exactly `expected` (surrounding blanks kept); none when the document has no source
// text, the position is unknown, or the text there is anything else (an entity, a comment, CDATA).
[[nodiscard]] std::optional<Fix> replace_element_text(const EsiDocument& document, SourcePos element, std::string_view expected,
                                                      std::string replacement, std::string description);

}  // namespace esi::rules
