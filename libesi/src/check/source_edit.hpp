#pragma once
// Safe fixes that rewrite the source text of elements: the rules know an element's position in the
// model; the fix needs the bytes, found in the document's source text and checked to be what the
// model read, so that a fix is never applied to text that differs from what the rule saw.

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

// Removes the attribute `name` from the start tag of the element at `element`, with the blanks
// before it (so `<Sm A="1" B="2">` becomes `<Sm B="2">`, and an attribute on a line of its own
// takes its line along). None when the start tag or the attribute cannot be found there.
[[nodiscard]] std::optional<Fix> remove_attribute(const EsiDocument& document, SourcePos element, std::string_view name,
                                                  std::string description);

// Removes the element at `copy` when its text, from its start tag to its end tag, is byte for
// byte that of the element at `original`: a copy-and-paste repeat whose removal loses nothing.
// When the copy stands alone on its lines, the blanks before it and its line ending go too.
// None when either element cannot be delimited or the two differ in any byte.
[[nodiscard]] std::optional<Fix> remove_identical_copy(const EsiDocument& document, SourcePos original, SourcePos copy,
                                                       std::string description);

}  // namespace esi::rules
