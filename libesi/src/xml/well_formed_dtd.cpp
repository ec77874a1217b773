// The XML 1.0 well-formedness check's DTD productions: the DOCTYPE, its internal subset and the
// declarations in it (element, attribute-list, entity, notation), and parameter-entity references
// between declarations. See well_formed_scanner.hpp.

#include <string>

#include "xml/well_formed_scanner.hpp"

namespace esi::xml_well_formed {

// [28] doctypedecl ::= '<!DOCTYPE' S Name (S ExternalID)? S? ('[' intSubset ']' S?)? '>'
bool Scanner::doctype() {
    const char* start = p_;
    p_ += 9;
    if (!require_space("after <!DOCTYPE")) return false;
    std::string_view root;
    if (!name(root, "DOCTYPE")) return false;
    if (skip_space() && (starts("SYSTEM") || starts("PUBLIC"))) {
        if (!external_id(false)) return false;
        checker_.external_subset = true;
        skip_space();
    }
    if (peek() == '[') {
        ++p_;
        if (!internal_subset(false)) return false;
        if (peek() != ']') return fail(start, "the DOCTYPE's internal subset is not closed");
        ++p_;
        skip_space();
    }
    if (peek() != '>') return fail(p_, "malformed DOCTYPE");
    ++p_;
    return true;
}

// [28b] intSubset ::= (markupdecl | DeclSep)*, up to ']' (or the end of a parameter entity).
bool Scanner::internal_subset(bool in_parameter_entity) {
    for (;;) {
        skip_space();
        if (at_end()) return in_parameter_entity || fail(p_, "the DOCTYPE is not closed");
        if (*p_ == ']' && !in_parameter_entity) return true;
        bool ok = true;
        if (starts("<!ELEMENT")) ok = element_declaration();
        else if (starts("<!ATTLIST")) ok = attlist_declaration();
        else if (starts("<!ENTITY")) ok = entity_declaration();
        else if (starts("<!NOTATION")) ok = notation_declaration();
        else if (starts("<!--")) ok = comment();
        else if (starts("<?")) ok = processing_instruction();
        else if (*p_ == '%') ok = parameter_entity_reference();
        else if (starts("<![")) {
            // [61] conditional sections belong to the external subset; in the replacement text of a
            // parameter entity they may be legal, but that text is then not checked further.
            if (in_parameter_entity) return true;
            return fail(p_, "conditional sections are only allowed in the external DTD subset");
        } else
            return fail(p_, "malformed markup declaration in the DOCTYPE");
        if (!ok) return false;
    }
}

bool Scanner::declaration_end(const char* what) {
    skip_space();
    if (peek() == '%') return fail(p_, "parameter-entity reference inside a markup declaration of the internal subset");
    if (peek() != '>') return fail(p_, std::string("malformed ") + what + " declaration");
    ++p_;
    return true;
}

// [45] elementdecl ::= '<!ELEMENT' S Name S contentspec S? '>'
bool Scanner::element_declaration() {
    p_ += 9;
    std::string_view element;
    if (!require_space("after <!ELEMENT") || !name(element, "element declaration") || !require_space("after the element name"))
        return false;
    if (starts("EMPTY")) p_ += 5;
    else if (starts("ANY")) p_ += 3;
    else if (peek() == '(') {
        ++p_;
        skip_space();
        if (starts("#PCDATA")) {
            // [51] Mixed ::= '(' S? '#PCDATA' (S? '|' S? Name)* S? ')*' | '(' S? '#PCDATA' S? ')'
            p_ += 7;
            bool alternatives = false;
            for (;;) {
                skip_space();
                if (peek() == ')') break;
                if (peek() != '|') return fail(p_, "malformed mixed content model");
                ++p_;
                skip_space();
                std::string_view child;
                if (!name(child, "mixed content model")) return false;
                alternatives = true;
            }
            ++p_;
            if (peek() == '*') ++p_;
            else if (alternatives) return fail(p_, "a mixed content model with element names must end with ')*'");
        } else if (!content_group(1)) {
            return false;
        }
    } else if (peek() == '%') {
        return fail(p_, "parameter-entity reference inside a markup declaration of the internal subset");
    } else {
        return fail(p_, "content model expected (EMPTY, ANY or a parenthesised model)");
    }
    return declaration_end("element");
}

// [48] cp ::= (Name | choice | seq) ('?' | '*' | '+')?
bool Scanner::content_particle(int depth) {
    if (peek() == '(') {
        ++p_;
        if (!content_group(depth + 1)) return false;
    } else {
        std::string_view child;
        if (!name(child, "content model")) return false;
        if (peek() == '?' || peek() == '*' || peek() == '+') ++p_;
    }
    return true;
}

// [49] choice / [50] seq, after the '('; with the occurrence indicator after the ')'.
bool Scanner::content_group(int depth) {
    if (depth > max_content_model_depth)
        return fail(p_, "content model nested deeper than " + std::to_string(max_content_model_depth) + " levels");
    skip_space();
    if (!content_particle(depth)) return false;
    char separator = 0;
    for (;;) {
        skip_space();
        const char c = peek();
        if (c == ')') {
            ++p_;
            break;
        }
        if (c != '|' && c != ',') return fail(p_, "malformed content model");
        if (separator && c != separator) return fail(p_, "a content model group mixes ',' and '|'");
        separator = c;
        ++p_;
        skip_space();
        if (!content_particle(depth)) return false;
    }
    if (peek() == '?' || peek() == '*' || peek() == '+') ++p_;
    return true;
}

// [52] AttlistDecl ::= '<!ATTLIST' S Name AttDef* S? '>'
bool Scanner::attlist_declaration() {
    p_ += 9;
    std::string_view element;
    if (!require_space("after <!ATTLIST") || !name(element, "attribute-list declaration")) return false;
    for (;;) {
        const bool spaced = skip_space();
        if (peek() == '>') {
            ++p_;
            return true;
        }
        if (peek() == '%') return fail(p_, "parameter-entity reference inside a markup declaration of the internal subset");
        if (!spaced) return fail(p_, "malformed attribute-list declaration");
        // [53] AttDef ::= S Name S AttType S DefaultDecl
        std::string_view attribute;
        if (!name(attribute, "attribute definition") || !require_space("after the attribute name")) return false;
        bool typed = false;
        for (std::string_view type : {"CDATA", "IDREFS", "IDREF", "ID", "ENTITIES", "ENTITY", "NMTOKENS", "NMTOKEN"}) {
            if (starts(type) && (class_of(peek(type.size())) & space)) {
                p_ += type.size();
                typed = true;
                break;
            }
        }
        if (!typed) {
            const bool notation = keyword_then_space("NOTATION");
            // [58] NotationType, [59] Enumeration
            if (peek() != '(') return fail(p_, "attribute type expected for " + quoted(attribute));
            ++p_;
            for (;;) {
                skip_space();
                if (notation) {
                    std::string_view n;
                    if (!name(n, "notation type")) return false;
                } else if (!nmtoken()) {
                    return false;
                }
                skip_space();
                if (peek() == ')') break;
                if (peek() != '|') return fail(p_, "malformed enumeration");
                ++p_;
            }
            ++p_;
        }
        if (!require_space("after the attribute type")) return false;
        // [60] DefaultDecl ::= '#REQUIRED' | '#IMPLIED' | (('#FIXED' S)? AttValue)
        if (starts("#REQUIRED")) p_ += 9;
        else if (starts("#IMPLIED")) p_ += 8;
        else {
            if (starts("#FIXED")) {
                p_ += 6;
                if (!require_space("after #FIXED")) return false;
            }
            if (!attribute_value(attribute)) return false;
        }
    }
}

// [70] EntityDecl ::= GEDecl | PEDecl
bool Scanner::entity_declaration() {
    p_ += 8;
    if (!require_space("after <!ENTITY")) return false;
    bool parameter = false;
    if (peek() == '%') {
        ++p_;
        if (!require_space("after '%' in a parameter-entity declaration")) return false;
        parameter = true;
    }
    std::string_view entity_name;
    if (!name(entity_name, "entity declaration") || !require_space("after the entity name")) return false;
    Entity entity;
    if (peek() == '"' || peek() == '\'') {
        if (!entity_value(entity.replacement)) return false;
    } else {
        if (!external_id(false)) return false;
        entity.external = true;
        // [76] NDataDecl ::= S 'NDATA' S Name (general entities only)
        const char* before = p_;
        if (skip_space() && starts("NDATA")) {
            if (parameter) return fail(p_, "a parameter entity cannot be unparsed (NDATA)");
            p_ += 5;
            std::string_view notation;
            if (!require_space("after NDATA") || !name(notation, "notation")) return false;
            entity.unparsed = true;
        } else {
            p_ = before;
        }
    }
    if (!declaration_end("entity")) return false;
    // The first declaration of a name binds it; later ones are ignored (section 4.2).
    auto& map = parameter ? checker_.parameter : checker_.general;
    map.try_emplace(std::string(entity_name), std::move(entity));
    return true;
}

// [9] EntityValue ::= '"' ([^%&"] | PEReference | Reference)* '"' | ...; the replacement text
// (section 4.5) has character references replaced and entity references kept.
bool Scanner::entity_value(std::string& replacement) {
    const char q = *p_;
    const char* start = ++p_;
    for (;;) {
        const char* run = p_;
        if (!scan_until((q == '"' ? quot : apos) | amp | percent)) return false;
        replacement.append(run, static_cast<std::size_t>(p_ - run));
        if (at_end()) return fail(start - 1, "the entity value is not closed");
        const char c = *p_;
        if (c == q) {
            ++p_;
            return true;
        }
        if (c == '%') return fail(p_, "parameter-entity reference inside a markup declaration of the internal subset");
        if (c == '&') {
            // Entity references are kept (they are resolved where the entity is used);
            // character references are replaced in the replacement text.
            const char* ref = p_;
            ParsedReference parsed;
            if (!parse_reference(parsed)) return false;
            if (parsed.character) append_utf8(replacement, parsed.value);
            else replacement.append(ref, static_cast<std::size_t>(p_ - ref));
            continue;
        }
        replacement += c;  // the other quote character
        ++p_;
    }
}

// [75] ExternalID ::= 'SYSTEM' S SystemLiteral | 'PUBLIC' S PubidLiteral S SystemLiteral
// With public_id_alone_allowed ([83] PublicID in a notation), the SystemLiteral may be missing.
bool Scanner::external_id(bool public_id_alone_allowed) {
    std::string_view literal;
    if (starts("SYSTEM")) {
        p_ += 6;
        if (!require_space("after SYSTEM") || !quoted_literal(literal, "system literal")) return false;
        return true;
    }
    if (!starts("PUBLIC")) return fail(p_, "SYSTEM or PUBLIC expected");
    p_ += 6;
    if (!require_space("after PUBLIC") || !quoted_literal(literal, "public identifier")) return false;
    // [13] PubidChar ::= #x20 | #xD | #xA | [a-zA-Z0-9] | [-'()+,./:=?;!*#@$_%]
    for (std::size_t i = 0; i < literal.size(); ++i) {
        const char c = literal[i];
        const bool ok = c == ' ' || c == '\r' || c == '\n' || ((c | 0x20) >= 'a' && (c | 0x20) <= 'z') || (c >= '0' && c <= '9') ||
                        std::strchr("-'()+,./:=?;!*#@$_%", c) != nullptr;
        if (!ok || c == '\0') return fail(literal.data() + i, "character not allowed in a public identifier");
    }
    const char* before = p_;
    if (skip_space() && (peek() == '"' || peek() == '\'')) {
        if (!quoted_literal(literal, "system literal")) return false;
        return true;
    }
    p_ = before;
    if (public_id_alone_allowed) return true;
    return fail(p_, "a system literal expected after the public identifier");
}

// [82] NotationDecl ::= '<!NOTATION' S Name S (ExternalID | PublicID) S? '>'
bool Scanner::notation_declaration() {
    p_ += 10;
    std::string_view notation;
    if (!require_space("after <!NOTATION") || !name(notation, "notation declaration") || !require_space("after the notation name") ||
        !external_id(true))
        return false;
    return declaration_end("notation");
}

// [69] PEReference ::= '%' Name ';' between declarations (DeclSep [28a]).
bool Scanner::parameter_entity_reference() {
    const char* percent_at = p_;
    ++p_;
    std::string_view entity;
    if (!name(entity, "parameter-entity reference")) return false;
    if (peek() != ';') return fail(percent_at, "parameter-entity reference " + quoted(entity) + " is not closed with ';'");
    ++p_;
    Entity* e = find(checker_.parameter, entity);
    if (!e || e->external) {
        // Not declared here, or never fetched: declarations may be out of sight from now on.
        checker_.unresolved_parameter_entities = true;
        return true;
    }
    if (e->declarations == Entity::State::good) return true;
    if (e->declarations == Entity::State::checking) return fail(percent_at, "parameter entity " + quoted(entity) + " refers to itself");
    if (checker_.entity_depth >= max_entity_depth)
        return fail(percent_at, "entities nested deeper than " + std::to_string(max_entity_depth) + " levels");
    e->declarations = Entity::State::checking;
    ++checker_.entity_depth;
    const EntityScope scope{scope_ ? scope_->offset : static_cast<std::size_t>(percent_at - begin_), entity};
    Scanner inner(checker_, e->replacement, &scope);
    const bool ok = inner.entity_declarations();
    --checker_.entity_depth;
    if (!ok) return false;
    e->declarations = Entity::State::good;
    return true;
}

}  // namespace esi::xml_well_formed
