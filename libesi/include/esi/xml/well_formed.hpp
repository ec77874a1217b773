#pragma once
// XML 1.0 well-formedness (W3C XML 1.0, fifth edition) for what pugixml accepts although the
// specification forbids it: pugixml is fast because it checks only what it needs to build a tree,
// while expat, libxml2 and TwinCAT reject a document that, for example, repeats an attribute,
// references an undeclared entity, holds "--" inside a comment, a control character, a
// character reference to one (&#0;) or a '<' inside an attribute value. The reader runs this
// check once on the text pugixml accepted, so that such a file gets the xml-syntax error every
// other XML processor gives it instead of being read silently.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include <pugixml.hpp>

#include "esi/encoding.hpp"

namespace esi {

struct WellFormednessFault {
    std::size_t offset = 0;  // byte offset in the checked text
    std::string message;     // what is wrong, without a "not well-formed" prefix
};

// The first fault in document order, or nothing for a well-formed document.
// `text` is the decoded UTF-8 text (valid UTF-8, byte-order mark removed); a std::string because
// the scan relies on the NUL byte after its end. `encoding` is what the bytes were (the XML
// declaration must agree with it). `parsed` is what pugixml built from it, parsed in
// place from a copy of `text` at `parse_buffer`, with parse_fragment (which keeps text after the
// root element as a node) and without error: the check relies on what pugixml verified (balanced
// tags, ASCII names, quoted attribute values) and looks only where pugixml is lenient.
// Nothing is expanded, loaded or fetched: the replacement text of an internal entity is checked
// where the entity is used, once per entity, and an external entity only for where it is used.
[[nodiscard]] std::optional<WellFormednessFault> find_well_formedness_fault(const std::string& text, SourceEncoding encoding,
                                                                          const pugi::xml_document& parsed, const char* parse_buffer);

// The same for XML given as element content rather than as a document (the xml: snippets of a
// YAML device source): elements, text and references, balanced, no DOCTYPE, so only the five
// predefined entities. Needs no pugixml tree.
[[nodiscard]] std::optional<WellFormednessFault> find_content_fault(const std::string& text);

}  // namespace esi
