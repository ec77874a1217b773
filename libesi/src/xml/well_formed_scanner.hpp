#pragma once
// The XML 1.0 well-formedness check's scanner (W3C Recommendation "Extensible Markup Language
// (XML) 1.0 (Fifth Edition)", https://www.w3.org/TR/xml/; production numbers [n] and constraint
// names refer to it). A Scanner makes one pass over one text; the Checker holds what the passes
// share (declared entities, the fault nearest the start). The productions live in one file per
// part of the grammar: well_formed_scanner.cpp (tokens: names, literals, forbidden characters),
// well_formed.cpp (the prolog, markup, references and the content of entities) and
// well_formed_dtd.cpp (the DOCTYPE and its declarations). The document's own elements are parsed
// by xml/tree_parser.hpp, which builds the reader's tree in the same pass and hands the rare
// constructs (comments, processing instructions, CDATA sections, references, names beyond ASCII)
// to these productions.

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "esi/text_span.hpp"
#include "esi/xml/well_formed.hpp"
#include "xml/well_formed_chars.hpp"

namespace esi::xml_well_formed {

bool is_predefined_entity(std::string_view name);

// The text in quotes, shortened for a message.
std::string quoted(std::string_view text);

// Entities declared in the internal DTD subset. Nothing is ever fetched: an external entity is
// only checked for where it is referenced.
struct Entity {
    enum class State : std::uint8_t { unchecked, checking, good };
    bool external = false;       // SYSTEM or PUBLIC
    bool unparsed = false;       // NDATA: may only be named in ENTITY attributes, never referenced
    std::string replacement;     // internal entities: the literal with character references replaced
    State content = State::unchecked;    // replacement text checked as element content [43]
    State attribute = State::unchecked;  // replacement text checked for '<' (WFC: No < in Attribute Values)
    State declarations = State::unchecked;  // parameter entities: replacement text checked as declarations
};

// Deeper entity nesting is refused rather than followed (libxml2 stops at 40 levels).
constexpr int max_entity_depth = 64;
// Deeper nesting of parentheses in an element declaration's content model is refused.
constexpr int max_content_model_depth = 256;

class Checker;

// Where a fault inside an entity's replacement text is reported: at the outermost reference in
// the document, naming the entity.
struct EntityScope {
    std::size_t offset = 0;
    std::string_view name;
};

// One pass over one text: the document, or the replacement text of an entity being checked.
class Scanner {
public:
    // `text` must stay alive and be followed by a NUL byte (a std::string's terminator, or the one
    // after a file's bytes): the character-data loops stop on it without a bounds test.
    Scanner(Checker& checker, std::string_view text, const EntityScope* scope)
        : checker_(checker), begin_(text.data()), end_(text.data() + text.size()), p_(begin_), scope_(scope) {}

    // [22] prolog: the XML declaration, comments, processing instructions and the DOCTYPE, up to
    // the '<' of the root element.
    bool prolog();
    bool markup();
    bool entity_content();     // [43] content, balanced, nothing left over
    bool entity_attribute();   // no '<', references allowed in attribute values
    bool entity_declarations();  // a parameter entity used between declarations

protected:
    // ---- basics --------------------------------------------------------------------------
    bool fail(const char* at, std::string message);
    bool at_end() const { return p_ >= end_; }
    char peek(std::size_t k = 0) const { return p_ + k < end_ ? p_[k] : '\0'; }
    bool starts(std::string_view s) const {
        return static_cast<std::size_t>(end_ - p_) >= s.size() && std::memcmp(p_, s.data(), s.size()) == 0;
    }
    bool skip_space() {
        const char* start = p_;
        while (class_of(*p_) & space) ++p_;  // the NUL after the text is not a space
        return p_ != start;
    }
    bool require_space(const char* what) { return skip_space() || fail(p_, std::string("whitespace expected ") + what); }
    // Advances until a byte of class `stops` (or the end); a forbidden character on the way is a fault.
    bool scan_until(std::uint16_t stops);
    bool checked_character();  // p_ at a `check` byte: a fault, or U+EFxx stepped over
    bool characters_until(std::uint16_t stop, std::string_view end, const char* start, const char* what);
    // [5] Name. ASCII names, nearly all of them, in a tight loop (the NUL after the text ends it);
    // the rest out of line.
    bool name(std::string_view& out, const char* what) {
        const char* start = p_;
        if (class_of(*p_) & name_start) {
            ++p_;
            while (class_of(*p_) & name_char) ++p_;
            if (!(class_of(*p_) & non_ascii)) {
                out = std::string_view(start, static_cast<std::size_t>(p_ - start));
                return true;
            }
        }
        return name_beyond_ascii(start, out, what);
    }
    bool name_beyond_ascii(const char* start, std::string_view& out, const char* what);
    bool nmtoken();
    bool keyword_then_space(std::string_view keyword);
    bool quoted_literal(std::string_view& out, const char* what);

    // ---- markup ---------------------------------------------------------------------------
    bool xml_declaration();
    bool declared_encoding_holds(std::string_view declared, const char* at);
    bool prolog_item(bool& doctype_seen);
    bool comment();
    bool processing_instruction();
    bool cdata_section();
    bool start_tag(bool& empty, std::string_view& element);
    bool end_tag(std::string_view& element);
    bool attribute_value(std::string_view attribute);
    struct ParsedReference {
        bool character = false;
        std::uint32_t value = 0;   // character references
        std::string_view name;     // entity references
    };
    bool parse_reference(ParsedReference& out);
    bool reference(bool in_attribute);
    bool content();

    // ---- DTD ------------------------------------------------------------------------------
    bool doctype();
    bool internal_subset(bool in_parameter_entity);
    bool element_declaration();
    bool content_particle(int depth);
    bool content_group(int depth);
    bool attlist_declaration();
    bool entity_declaration();
    bool entity_value(std::string& replacement);
    bool external_id(bool public_id_alone_allowed);
    bool notation_declaration();
    bool parameter_entity_reference();
    bool declaration_end(const char* what);

    Checker& checker_;
    const char* begin_;
    const char* end_;
    const char* p_;
    const EntityScope* scope_;
    std::vector<std::string_view> open_;  // names of the open elements
};

class Checker {
public:
    Checker(std::string_view text, SourceEncoding encoding) : encoding(encoding), text_(text) {}

    std::size_t first_beyond_ascii() const {
        for (std::size_t i = 0; i < text_.size(); ++i)
            if (static_cast<Byte>(text_[i]) >= 0x80) return i;
        return std::string::npos;
    }

    std::optional<WellFormednessFault> run_content() {
        Scanner scanner(*this, text_, nullptr);
        scanner.entity_content();
        return std::move(fault_);
    }

    // Keeps the fault nearest to the start of the text.
    bool fail(std::size_t offset, std::string message) {
        if (!fault_ || offset < fault_->offset) fault_ = WellFormednessFault{offset, std::move(message)};
        return false;
    }
    [[nodiscard]] bool faulted() const { return fault_.has_value(); }
    [[nodiscard]] const std::optional<WellFormednessFault>& fault() const { return fault_; }

    // WFC: Entity Declared. With an external subset or parameter-entity references that were not
    // followed, a declaration may be out of sight; then an undeclared name is a validity error,
    // not a fault of well-formedness (unless the document declares itself standalone).
    bool undeclared_entities_allowed() const { return (external_subset || unresolved_parameter_entities) && !standalone; }

    std::unordered_map<std::string, Entity, std::hash<std::string>, std::equal_to<>> general;
    std::unordered_map<std::string, Entity, std::hash<std::string>, std::equal_to<>> parameter;
    bool external_subset = false;
    bool unresolved_parameter_entities = false;
    const SourceEncoding encoding;  // what the decoder found (byte-order mark, UTF-16 shape, declaration)
    bool standalone = false;
    bool doctype_seen = false;
    // The document's comments, from '<' to after '>' (offsets in the text; not those of entities).
    std::vector<TextSpan> comments;
    // Where the DOCTYPE is: from its '<' to after its '>' (offsets in the text).
    std::size_t doctype_begin = 0;
    std::size_t doctype_end = 0;
    int entity_depth = 0;
    std::vector<std::string_view> attributes;  // names in the current start tag
    std::unordered_set<std::string_view> attribute_set;  // the same, for tags with many attributes

private:
    std::string_view text_;
    std::optional<WellFormednessFault> fault_;
};

// The declared entity named `name`, or null.
Entity* find(std::unordered_map<std::string, Entity, std::hash<std::string>, std::equal_to<>>& map, std::string_view name);

// Inline: it is the inner loop of comments, processing instructions, CDATA sections and entity
// values.
inline bool Scanner::scan_until(std::uint16_t stops) {
    const std::uint16_t mask = stops | check;
    for (;;) {
        // The NUL after the text has the `check` class: the loop needs no bounds test.
        while (!(class_of(*p_) & mask)) ++p_;
        if (p_ >= end_) {
            p_ = end_;
            return true;
        }
        if (class_of(*p_) & stops) return true;
        if (!checked_character()) return false;
    }
}

}  // namespace esi::xml_well_formed
