// XML 1.0 well-formedness (W3C Recommendation "Extensible Markup Language (XML) 1.0 (Fifth
// Edition)", https://www.w3.org/TR/xml/; production numbers [n] and constraint names below refer to
// it). One forward pass over the text: markup is parsed by the grammar, character data is skipped
// through a byte-class table until the next byte that can matter, so the pass costs about as much
// as reading the text once. The parts of the grammar are split as well_formed_scanner.hpp says.

#include "esi/xml/well_formed.hpp"

#include <initializer_list>

#include "xml/well_formed_scanner.hpp"

namespace esi {

namespace xml_well_formed {

// ---- document ------------------------------------------------------------------------------

// [22] prolog ::= XMLDecl? Misc* (doctypedecl Misc*)?, up to the '<' of the root element.
bool Scanner::prolog() {
    // [23] XMLDecl is allowed only at the very start (the byte-order mark is gone already).
    if (starts("<?xml") && (class_of(peek(5)) & space || peek(5) == '?'))
        if (!xml_declaration()) return false;
    bool doctype_seen = false;
    for (;;) {
        skip_space();
        if (at_end()) return fail(p_, "no root element");
        if (*p_ == '<' && (class_of(peek(1)) & (name_start | non_ascii))) return true;
        if (!prolog_item(doctype_seen)) return false;
    }
}

// One construct starting at '<' inside or after the root element.
bool Scanner::markup() {
    const char next = peek(1);
    if (next == '/') {
        std::string_view element;
        return end_tag(element);
    }
    if (next == '?') return processing_instruction();
    if (next == '!') {
        if (starts("<!--")) return comment();
        if (starts("<![CDATA[")) return cdata_section();
        if (starts("<!DOCTYPE")) return fail(p_, "a DOCTYPE is only allowed before the root element");
        return fail(p_, "markup declaration outside the DOCTYPE");
    }
    bool empty = false;
    std::string_view element;
    return start_tag(empty, element);
}

// [22] prolog: [27] Misc (comment, processing instruction; white space is skipped by the caller)
// or the one DOCTYPE.
bool Scanner::prolog_item(bool& doctype_seen) {
    if (starts("<!--")) return comment();
    if (starts("<?")) return processing_instruction();
    if (starts("<!DOCTYPE")) {
        if (doctype_seen) return fail(p_, "a second DOCTYPE");
        doctype_seen = true;
        checker_.doctype_seen = true;
        checker_.doctype_begin = static_cast<std::size_t>(p_ - begin_);
        const bool ok = doctype();
        checker_.doctype_end = static_cast<std::size_t>(p_ - begin_);
        return ok;
    }
    if (starts("<![CDATA[")) return fail(p_, "a CDATA section outside the root element");
    if (*p_ == '<') return fail(p_, "markup before the root element that is not a comment, processing instruction or DOCTYPE");
    return fail(p_, "text before the root element");
}

// [23] XMLDecl ::= '<?xml' VersionInfo EncodingDecl? SDDecl? S? '?>'
bool Scanner::xml_declaration() {
    const char* start = p_;
    p_ += 5;
    bool spaced = skip_space();
    auto equals = [&] {
        skip_space();
        if (peek() != '=') return fail(p_, "'=' expected in the XML declaration");
        ++p_;
        skip_space();
        return true;
    };
    std::string_view value;
    if (!spaced || !starts("version")) return fail(p_, "the XML declaration must begin with version=\"1.0\"");
    p_ += 7;
    if (!equals() || !quoted_literal(value, "version number")) return false;
    // [26] VersionNum ::= '1.' [0-9]+
    bool version_ok = value.size() > 2 && value.substr(0, 2) == "1.";
    for (std::size_t i = 2; version_ok && i < value.size(); ++i) version_ok = value[i] >= '0' && value[i] <= '9';
    if (!version_ok) return fail(p_ - value.size() - 1, "XML version " + quoted(value) + " is not 1.x");
    spaced = skip_space();
    if (spaced && starts("encoding")) {
        p_ += 8;
        if (!equals() || !quoted_literal(value, "encoding name")) return false;
        // [81] EncName ::= [A-Za-z] ([A-Za-z0-9._] | '-')*
        bool name_ok = !value.empty() && ((value[0] | 0x20) >= 'a' && (value[0] | 0x20) <= 'z');
        for (std::size_t i = 1; name_ok && i < value.size(); ++i) {
            const char c = value[i];
            name_ok = ((c | 0x20) >= 'a' && (c | 0x20) <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
        }
        if (!name_ok) return fail(p_ - value.size() - 1, "encoding name " + quoted(value) + " is malformed");
        if (!declared_encoding_holds(value, p_ - value.size() - 1)) return false;
        spaced = skip_space();
    }
    if (spaced && starts("standalone")) {
        p_ += 10;
        if (!equals() || !quoted_literal(value, "standalone value")) return false;
        if (value != "yes" && value != "no") return fail(p_ - value.size() - 1, "standalone must be \"yes\" or \"no\", not " + quoted(value));
        checker_.standalone = value == "yes";
        skip_space();
    }
    if (!starts("?>")) return fail(p_ > start ? p_ : start, "malformed XML declaration (version, encoding, standalone, in this order)");
    p_ += 2;
    return true;
}

// Section 4.3.3: a document in another encoding than its declaration names is a fatal error.
// Where the bytes tell (a byte-order mark, UTF-16, bytes beyond ASCII) the two must agree; the
// decoder reads UTF-8, UTF-16, ISO-8859-1 and Windows-1252, so a document in any other encoding
// is refused when it has bytes beyond ASCII (which would be read wrongly), and read when it has none.
bool Scanner::declared_encoding_holds(std::string_view declared, const char* at) {
    std::string name(declared);
    for (char& c : name) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 32 : c);
    const auto one_of = [&](std::initializer_list<std::string_view> names) {
        for (const auto n : names)
            if (name == n) return true;
        return false;
    };
    const bool wide = one_of({"UTF-16", "UTF-16LE", "UTF-16BE", "UCS-2", "ISO-10646-UCS-2", "UTF-32", "UTF-32LE", "UTF-32BE", "UCS-4",
                              "ISO-10646-UCS-4"});
    const SourceEncoding actual = checker_.encoding;
    const bool utf16 = actual == SourceEncoding::utf16le || actual == SourceEncoding::utf16be;
    if (wide && !utf16) return fail(at, "the XML declaration names " + quoted(declared) + ", but the document is in 8-bit bytes");
    if (utf16 && !wide) return fail(at, "the document is in UTF-16, but the XML declaration names " + quoted(declared));
    if (actual == SourceEncoding::utf8_bom && !one_of({"UTF-8", "UTF8"}))
        return fail(at, "the byte-order mark says UTF-8, but the XML declaration names " + quoted(declared));
    if (wide || one_of({"UTF-8", "UTF8", "ISO-8859-1", "ISO8859-1", "LATIN1", "ISO_8859-1", "ISO-8859-15", "WINDOWS-1252", "CP1252"}))
        return true;
    const std::size_t beyond = checker_.first_beyond_ascii();
    if (beyond == std::string::npos) return true;
    return fail(begin_ + beyond, one_of({"US-ASCII", "ASCII"})
                                     ? "a byte beyond ASCII in a document whose XML declaration names " + quoted(declared)
                                     : "the document is in " + quoted(declared) +
                                           ", which is not read (UTF-8, UTF-16, ISO-8859-1 and Windows-1252 are), and has bytes beyond ASCII");
}

// [15] Comment ::= '<!--' ((Char - '-') | ('-' (Char - '-')))* '-->'
bool Scanner::comment() {
    const char* start = p_;
    p_ += 4;
    for (;;) {
        if (!scan_until(hyphen)) return false;
        if (at_end()) return fail(start, "the comment is not closed");
        if (peek(1) == '-') {
            if (peek(2) == '>') {
                p_ += 3;
                if (!scope_) checker_.comments.push_back({static_cast<std::size_t>(start - begin_), static_cast<std::size_t>(p_ - begin_)});
                return true;
            }
            return fail(p_, "'--' inside a comment (only allowed in the closing '-->')");
        }
        ++p_;
    }
}

// [16] PI ::= '<?' PITarget (S (Char* - (Char* '?>' Char*)))? '?>'
bool Scanner::processing_instruction() {
    const char* start = p_;
    p_ += 2;
    std::string_view target;
    if (!name(target, "processing instruction target")) return false;
    // [17] PITarget excludes 'xml' in any case: the XML declaration is only allowed at the start.
    if (target.size() == 3 && (target[0] | 0x20) == 'x' && (target[1] | 0x20) == 'm' && (target[2] | 0x20) == 'l')
        return fail(start, target == "xml" ? "an XML declaration is only allowed at the very start of the document"
                                           : "the processing instruction target " + quoted(target) + " is reserved");
    if (starts("?>")) {
        p_ += 2;
        return true;
    }
    if (!skip_space()) return fail(p_, "whitespace expected after the processing instruction target");
    return characters_until(question, "?>", start, "the processing instruction");
}

// Characters up to and over `end` (whose first byte has class `stop`), each one checked.
bool Scanner::characters_until(std::uint16_t stop, std::string_view end, const char* start, const char* what) {
    for (;;) {
        if (!scan_until(stop)) return false;
        if (at_end()) return fail(start, std::string(what) + " is not closed");
        if (starts(end)) {
            p_ += end.size();
            return true;
        }
        ++p_;
    }
}

// [18] CDSect ::= '<![CDATA[' (Char* - (Char* ']]>' Char*)) ']]>'
bool Scanner::cdata_section() {
    const char* start = p_;
    p_ += 9;
    return characters_until(rsqb, "]]>", start, "the CDATA section");
}

// [40] STag / [44] EmptyElemTag; p_ at '<'.
bool Scanner::start_tag(bool& empty, std::string_view& element) {
    const char* open = p_;
    ++p_;
    if (!name(element, "element")) return false;
    auto& names = checker_.attributes;
    auto& set = checker_.attribute_set;
    names.clear();
    set.clear();
    for (;;) {
        const bool spaced = skip_space();
        if (at_end()) return fail(open, "the start tag of " + quoted(element) + " is not closed");
        if (*p_ == '>') {
            ++p_;
            empty = false;
            return true;
        }
        if (*p_ == '/' && peek(1) == '>') {
            p_ += 2;
            empty = true;
            return true;
        }
        if (!spaced) return fail(p_, "whitespace expected before an attribute of " + quoted(element));
        const char* attribute_at = p_;
        std::string_view attribute;
        if (!name(attribute, "attribute")) return false;
        // WFC: Unique Att Spec. A linear search for the usual few attributes, a set for many.
        bool repeated = false;
        if (names.size() < 16) {
            for (const auto n : names) repeated = repeated || n == attribute;
            names.push_back(attribute);
            if (names.size() == 16) set.insert(names.begin(), names.end());
        } else {
            repeated = !set.insert(attribute).second;
        }
        if (repeated) return fail(attribute_at, "attribute " + quoted(attribute) + " is given twice in the start tag of " + quoted(element));
        skip_space();
        if (peek() != '=') return fail(p_, "'=' expected after attribute " + quoted(attribute));
        ++p_;
        skip_space();
        if (!attribute_value(attribute)) return false;
    }
}

// [10] AttValue ::= '"' ([^<&"] | Reference)* '"' | "'" ([^<&'] | Reference)* "'"
bool Scanner::attribute_value(std::string_view attribute) {
    const char q = peek();
    if (q != '"' && q != '\'') return fail(p_, "the value of attribute " + quoted(attribute) + " must be quoted");
    const char* start = p_++;
    for (;;) {
        p_ = find_first(p_, end_, value_stop_bytes);
        if (at_end()) return fail(start, "the value of attribute " + quoted(attribute) + " is not closed");
        const char c = *p_;
        if (c == q) {
            ++p_;
            return true;
        }
        if (c == '<') return fail(p_, "'<' inside the value of attribute " + quoted(attribute) + " (write &lt;)");
        if (c == '&') {
            if (!reference(true)) return false;
        } else if (class_of(c) & check) {
            if (!checked_character()) return false;
        } else {
            ++p_;  // the other quote character
        }
    }
}

// [67] Reference ::= EntityRef | CharRef, its syntax and WFC: Legal Character; p_ at '&', left
// after the ';'.
bool Scanner::parse_reference(ParsedReference& out) {
    const char* amp_at = p_;
    if (peek(1) == '#') {
        // [66] CharRef ::= '&#' [0-9]+ ';' | '&#x' [0-9a-fA-F]+ ';'
        p_ += 2;
        const bool hex = peek() == 'x';
        if (hex) ++p_;
        std::uint32_t value = 0;
        const char* digits = p_;
        while (p_ < end_) {
            const char c = *p_;
            int digit = -1;
            if (c >= '0' && c <= '9') digit = c - '0';
            else if (hex && (c | 0x20) >= 'a' && (c | 0x20) <= 'f') digit = (c | 0x20) - 'a' + 10;
            if (digit < 0) break;
            value = value > 0x10FFFF ? value : value * (hex ? 16 : 10) + static_cast<std::uint32_t>(digit);
            ++p_;
        }
        if (p_ == digits || peek() != ';')
            return fail(amp_at, "malformed character reference " + quoted(std::string_view(amp_at, static_cast<std::size_t>(p_ - amp_at) + 1)) +
                                    " (&#decimal; or &#xhex;)");
        ++p_;
        if (!is_xml_char(value))
            return fail(amp_at, "character reference " + quoted(std::string_view(amp_at, static_cast<std::size_t>(p_ - amp_at))) +
                                    " refers to " + (value > 0x10FFFF ? std::string("no Unicode code point") : code_point_name(value)) +
                                    ", which XML does not allow");
        out = ParsedReference{true, value, {}};
        return true;
    }
    // [68] EntityRef ::= '&' Name ';'
    ++p_;
    std::string_view entity;
    if (!(class_of(peek()) & (name_start | non_ascii)))
        return fail(amp_at, "'&' that starts no reference (write &amp; for an ampersand)");
    if (!name(entity, "entity reference")) return false;
    if (peek() != ';')
        return fail(amp_at, "entity reference " + quoted(std::string_view(amp_at, static_cast<std::size_t>(p_ - amp_at))) +
                                " is not closed with ';' (write &amp; for an ampersand)");
    ++p_;
    out = ParsedReference{false, 0, entity};
    return true;
}

// A reference in content or in an attribute value, resolved: WFC Entity Declared, Parsed Entity,
// No External Entity References, No < in Attribute Values, No Recursion.
bool Scanner::reference(bool in_attribute) {
    const char* amp_at = p_;
    ParsedReference parsed;
    if (!parse_reference(parsed)) return false;
    if (parsed.character) return true;
    const std::string_view entity = parsed.name;
    if (is_predefined_entity(entity)) return true;
    Entity* e = find(checker_.general, entity);
    if (!e) {
        if (checker_.undeclared_entities_allowed()) return true;
        return fail(amp_at, "undefined entity " + quoted("&" + std::string(entity) + ";") +
                                (checker_.doctype_seen ? std::string(" (the DOCTYPE does not declare it)")
                                                       : std::string(" (XML predefines only &lt; &gt; &amp; &apos; &quot;)")));
    }
    if (e->unparsed) return fail(amp_at, "reference to the unparsed (NDATA) entity " + quoted(entity));  // WFC: Parsed Entity
    if (e->external) {
        if (in_attribute) return fail(amp_at, "reference to the external entity " + quoted(entity) + " in an attribute value");
        return true;  // never fetched, so nothing more to check
    }
    Entity::State& state = in_attribute ? e->attribute : e->content;
    if (state == Entity::State::good) return true;
    if (state == Entity::State::checking) return fail(amp_at, "entity " + quoted(entity) + " refers to itself");  // WFC: No Recursion
    if (checker_.entity_depth >= max_entity_depth)
        return fail(amp_at, "entities nested deeper than " + std::to_string(max_entity_depth) + " levels");
    state = Entity::State::checking;
    ++checker_.entity_depth;
    const EntityScope scope{scope_ ? scope_->offset : static_cast<std::size_t>(amp_at - begin_), entity};
    Scanner inner(checker_, e->replacement, &scope);
    const bool ok = in_attribute ? inner.entity_attribute() : inner.entity_content();
    --checker_.entity_depth;
    if (!ok) return false;
    state = Entity::State::good;
    return true;
}

// [43] content over a whole replacement text: balanced elements and nothing left open.
bool Scanner::content() {
    open_.clear();
    for (;;) {
        if (!scan_until(lt | amp | rsqb)) return false;
        if (at_end()) return open_.empty() || fail(p_, "element " + quoted(open_.back()) + " is not closed");
        if (*p_ == '&') {
            if (!reference(false)) return false;
        } else if (*p_ == ']') {
            if (starts("]]>")) return fail(p_, "']]>' in character data (write ]]&gt;)");
            ++p_;
        } else if (peek(1) == '/') {
            const char* at = p_;
            std::string_view element;
            if (!end_tag(element)) return false;
            if (open_.empty() || open_.back() != element)
                return fail(at, open_.empty() ? "end tag " + quoted(element) + " without a start tag"
                                              : "end tag " + quoted(element) + " does not match " + quoted(open_.back()));
            open_.pop_back();
        } else if (peek(1) == '!' || peek(1) == '?') {
            if (!markup()) return false;
        } else {
            bool empty = false;
            std::string_view element;
            if (!start_tag(empty, element)) return false;
            if (!empty) open_.push_back(element);
        }
    }
}

// [42] ETag ::= '</' Name S? '>'
bool Scanner::end_tag(std::string_view& element) {
    const char* open = p_;
    p_ += 2;
    if (!name(element, "end tag")) return false;
    skip_space();
    if (peek() != '>') return fail(open, "malformed end tag " + quoted(element));
    ++p_;
    return true;
}

bool Scanner::entity_content() { return content(); }

bool Scanner::entity_attribute() {
    for (;;) {
        if (!scan_until(lt | amp)) return false;
        if (at_end()) return true;
        if (*p_ == '<') return fail(p_, "'<' where the entity is used in an attribute value");
        if (!reference(true)) return false;
    }
}

bool Scanner::entity_declarations() { return internal_subset(true); }

}  // namespace xml_well_formed

std::optional<WellFormednessFault> find_content_fault(const std::string& text) {
    xml_well_formed::Checker checker(text, SourceEncoding::utf8);
    return checker.run_content();
}

}  // namespace esi
