// The XML 1.0 well-formedness check's tokens: names, name tokens, keywords, literals, and the
// characters XML forbids. See well_formed_scanner.hpp.

#include "xml/well_formed_scanner.hpp"

#include "esi/diagnostic.hpp"

namespace esi::xml_well_formed {

bool is_predefined_entity(std::string_view name) {
    return name == "lt" || name == "gt" || name == "amp" || name == "apos" || name == "quot";
}

std::string quoted(std::string_view text) { return "'" + excerpt(text) + "'"; }

Entity* find(std::unordered_map<std::string, Entity, std::hash<std::string>, std::equal_to<>>& map, std::string_view name) {
    const auto it = map.find(std::string(name));
    return it == map.end() ? nullptr : &it->second;
}

bool Scanner::fail(const char* at, std::string message) {
    if (scope_) return checker_.fail(scope_->offset, "in the replacement text of entity " + quoted(scope_->name) + ": " + message);
    const char* clamped = at < begin_ ? begin_ : at > end_ ? end_ : at;
    return checker_.fail(static_cast<std::size_t>(clamped - begin_), std::move(message));
}

bool Scanner::checked_character() {
    const Byte b = static_cast<Byte>(*p_);
    if (b == 0xEF) {
        if (end_ - p_ >= 3 && static_cast<Byte>(p_[1]) == 0xBF && (static_cast<Byte>(p_[2]) == 0xBE || static_cast<Byte>(p_[2]) == 0xBF))
            return fail(p_, "character " + code_point_name(static_cast<Byte>(p_[2]) == 0xBE ? 0xFFFE : 0xFFFF) +
                                " is not allowed in XML (a non-character)");
        ++p_;
        return true;
    }
    return fail(p_, "character " + code_point_name(b) + " is not allowed in XML 1.0 (only tab, line feed and carriage return "
                                                          "among the control characters)");
}

// Names beyond ASCII: each character decoded and checked against [4] and [4a].
bool Scanner::name_beyond_ascii(const char* start, std::string_view& out, const char* what) {
    for (bool first = p_ == start; p_ < end_ && (class_of(*p_) & non_ascii); first = false) {
        int length = 0;
        const std::uint32_t cp = decode_utf8(p_, end_, length);
        if (length == 0) break;
        if (!(first ? is_name_start(cp) : is_name_char(cp)))
            return fail(p_, std::string("character ") + code_point_name(cp) + (first ? " cannot start a name (" : " is not allowed in a name (") +
                                what + ")");
        p_ += length;
        while (class_of(*p_) & name_char) ++p_;
    }
    if (p_ == start) return fail(p_, std::string("a name expected (") + what + ")");
    out = std::string_view(start, static_cast<std::size_t>(p_ - start));
    return true;
}

// [7] Nmtoken: one or more NameChar.
bool Scanner::nmtoken() {
    const char* start = p_;
    while (p_ < end_) {
        const std::uint16_t c = class_of(*p_);
        if (!(c & non_ascii)) {
            if (!(c & name_char)) break;
            ++p_;
            continue;
        }
        int length = 0;
        const std::uint32_t cp = decode_utf8(p_, end_, length);
        if (length == 0 || !is_name_char(cp)) break;
        p_ += length;
    }
    return p_ != start || fail(p_, "a name token expected in the enumeration");
}

bool Scanner::keyword_then_space(std::string_view keyword) {
    if (!starts(keyword)) return false;
    if (!(class_of(peek(keyword.size())) & space)) return false;
    p_ += keyword.size();
    skip_space();
    return true;
}

// A quoted literal without references (SystemLiteral [11], or the XML declaration's values).
bool Scanner::quoted_literal(std::string_view& out, const char* what) {
    const char q = peek();
    if (q != '"' && q != '\'') return fail(p_, std::string("a quoted ") + what + " expected");
    const char* start = ++p_;
    if (!scan_until(q == '"' ? quot : apos)) return false;
    if (at_end()) return fail(start - 1, std::string("the ") + what + " is not closed");
    out = std::string_view(start, static_cast<std::size_t>(p_ - start));
    ++p_;
    return true;
}
}  // namespace esi::xml_well_formed
