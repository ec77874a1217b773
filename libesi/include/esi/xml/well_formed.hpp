#pragma once
// XML 1.0 well-formedness (W3C XML 1.0, fifth edition), as expat, libxml2 and TwinCAT check it: a
// document that, for example, repeats an attribute, references an undeclared entity, holds "--"
// inside a comment, a control character, a character reference to one (&#0;) or a '<' inside an
// attribute value is refused. The ESI reader checks this in the same pass that builds its tree
// (xml/tree_parser.hpp), so that such a file gets the xml-syntax error every other XML processor
// gives it instead of being read silently.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "esi/encoding.hpp"

namespace esi {

struct WellFormednessFault {
    std::size_t offset = 0;  // byte offset in the checked text
    std::string message;     // what is wrong, without a "not well-formed" prefix
};

// The first fault in document order, or nothing for a well-formed document.
// `text` is the decoded UTF-8 text (valid UTF-8, byte-order mark removed); a std::string because
// the scan relies on the NUL byte after its end. `encoding` is what the bytes were (the XML
// declaration must agree with it). Nothing is expanded, loaded or fetched: the replacement text
// of an internal entity is checked where the entity is used, once per entity, and an external
// entity only for where it is used.
[[nodiscard]] std::optional<WellFormednessFault> find_well_formedness_fault(const std::string& text, SourceEncoding encoding);

// The same for XML given as element content rather than as a document (the xml: snippets of a
// YAML device source): elements, text and references, balanced, no DOCTYPE, so only the five
// predefined entities.
[[nodiscard]] std::optional<WellFormednessFault> find_content_fault(const std::string& text);

}  // namespace esi
