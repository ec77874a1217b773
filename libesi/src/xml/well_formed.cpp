// XML 1.0 well-formedness (W3C Recommendation "Extensible Markup Language (XML) 1.0 (Fifth
// Edition)", https://www.w3.org/TR/xml/; production numbers [n] and constraint names below refer to
// it). One forward pass over the text: markup is parsed by the grammar, character data is skipped
// through a byte-class table until the next byte that can matter, so the pass costs about as much
// as reading the text once.

#include "esi/xml/well_formed.hpp"

#include <array>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "esi/diagnostic.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace esi {

namespace {

using Byte = unsigned char;

// Byte classes. `check` marks the bytes a scan must look at whatever it is looking for: NUL and
// the C0 controls XML forbids ([2] Char allows only #x9, #xA and #xD below #x20), and 0xEF, the
// lead byte of the non-characters U+FFFE and U+FFFF. The text is valid UTF-8 (the decoder made it
// so), which rules out surrogates and code points above U+10FFFF.
enum : std::uint16_t {
    check = 1u << 0,
    lt = 1u << 1,         // <
    amp = 1u << 2,        // &
    rsqb = 1u << 3,       // ]
    quot = 1u << 4,       // "
    apos = 1u << 5,       // '
    hyphen = 1u << 6,     // -
    question = 1u << 7,   // ?
    percent = 1u << 8,    // %
    name_start = 1u << 9, // ASCII NameStartChar [4]
    name_char = 1u << 10, // ASCII NameChar [4a]
    space = 1u << 11,     // S [3]
    non_ascii = 1u << 12,
    candidate = 1u << 13,  // a byte the document walk stops at (see Scanner::walk)
};

constexpr std::array<std::uint16_t, 256> make_classes() {
    std::array<std::uint16_t, 256> c{};
    for (int b = 0; b < 0x20; ++b)
        if (b != 0x09 && b != 0x0A && b != 0x0D) c[b] |= check;
    c[0xEF] |= check;
    for (int b = 0x80; b < 0x100; ++b) c[b] |= non_ascii;
    c['<'] |= lt;
    c['&'] |= amp;
    c[']'] |= rsqb;
    c['"'] |= quot;
    c['\''] |= apos;
    c['-'] |= hyphen;
    c['?'] |= question;
    c['%'] |= percent;
    for (int b = 'A'; b <= 'Z'; ++b) c[b] |= name_start | name_char;
    for (int b = 'a'; b <= 'z'; ++b) c[b] |= name_start | name_char;
    c['_'] |= name_start | name_char;
    c[':'] |= name_start | name_char;
    for (int b = '0'; b <= '9'; ++b) c[b] |= name_char;
    c['-'] |= name_char;
    c['.'] |= name_char;
    for (int b : {0x20, 0x09, 0x0A, 0x0D}) c[b] |= space;
    for (int b = 0; b < 0x100; ++b)
        if ((c[b] & (check | non_ascii)) || b == '!' || b == '&' || b == '=' || b == '?' || b == ']') c[b] |= candidate;
    return c;
}

constexpr std::array<std::uint16_t, 256> classes = make_classes();

inline std::uint16_t class_of(char c) { return classes[static_cast<Byte>(c)]; }

// A set of bytes as two 16-entry tables: byte b is in the set when low[b & 15] & high[b >> 4] is
// not zero. Each bit of the tables stands for one high nibble (or a group of them) and marks the
// low nibbles that belong with it. The same tables drive the scalar and the vector search.
struct ByteSet {
    std::array<std::uint8_t, 16> low{};
    std::array<std::uint8_t, 16> high{};
    [[nodiscard]] constexpr bool contains(Byte b) const { return (low[b & 15] & high[b >> 4]) != 0; }
};

// Adds the bytes whose class has any of `bits` to the set, one table bit per high nibble in use.
constexpr ByteSet make_byte_set(const std::array<std::uint16_t, 256>& byte_classes, std::uint16_t bits) {
    ByteSet set;
    std::uint8_t next_bit = 1;
    for (int high = 0; high < 16; ++high) {
        std::uint8_t lows = 0;
        for (int low = 0; low < 16; ++low) lows |= (byte_classes[high * 16 + low] & bits) ? 1 : 0;
        if (!lows) continue;
        // Rows with every low nibble share one bit; the others need their own (at most seven).
        bool full = true;
        for (int low = 0; low < 16; ++low) full = full && (byte_classes[high * 16 + low] & bits);
        const std::uint8_t bit = full ? 0x80 : next_bit;
        if (!full) next_bit = static_cast<std::uint8_t>(next_bit << 1);
        set.high[high] |= bit;
        for (int low = 0; low < 16; ++low)
            if (byte_classes[high * 16 + low] & bits) set.low[low] |= bit;
    }
    return set;
}

// True when the set holds exactly the bytes of the classes (a set needing more than seven
// partial rows would not).
constexpr bool holds_exactly(const ByteSet& set, const std::array<std::uint16_t, 256>& byte_classes, std::uint16_t bits) {
    for (int b = 0; b < 256; ++b)
        if (set.contains(static_cast<Byte>(b)) != ((byte_classes[b] & bits) != 0)) return false;
    return true;
}

// Stops of the document walk, and of an attribute value (either quote, '<', '&', and what `check` marks).
constexpr std::uint16_t value_stops = quot | apos | lt | amp | check;
constexpr ByteSet candidate_bytes = make_byte_set(classes, candidate);
constexpr ByteSet value_stop_bytes = make_byte_set(classes, value_stops);
static_assert(holds_exactly(candidate_bytes, classes, candidate));
static_assert(holds_exactly(value_stop_bytes, classes, value_stops));

// The first byte of `set` in [p, end), or end.
const char* find_scalar(const char* p, const char* end, const ByteSet& set) {
    while (p < end && !set.contains(static_cast<Byte>(*p))) ++p;
    return p;
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same, 32 bytes per step: both nibbles of every byte are looked up at once (vpshufb) and
// ANDed. On ordinary files most 32-byte blocks hold no stop, so this runs at a fraction of an
// instruction per byte; it is most of the check's cost.
[[gnu::target("avx2")]] const char* find_avx2(const char* p, const char* end, const ByteSet& set) {
    const __m256i low_table = _mm256_broadcastsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(set.low.data())));
    const __m256i high_table = _mm256_broadcastsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(set.high.data())));
    const __m256i nibble = _mm256_set1_epi8(0x0F);
    while (end - p >= 32) {
        const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
        const __m256i low = _mm256_shuffle_epi8(low_table, _mm256_and_si256(v, nibble));
        const __m256i high = _mm256_shuffle_epi8(high_table, _mm256_and_si256(_mm256_srli_epi16(v, 4), nibble));
        const __m256i none = _mm256_cmpeq_epi8(_mm256_and_si256(low, high), _mm256_setzero_si256());
        const auto hits = ~static_cast<std::uint32_t>(_mm256_movemask_epi8(none));
        if (hits != 0) return p + __builtin_ctz(hits);
        p += 32;
    }
    return find_scalar(p, end, set);
}

const char* find_first(const char* p, const char* end, const ByteSet& set) {
    static const auto find = __builtin_cpu_supports("avx2") ? find_avx2 : find_scalar;
    return find(p, end, set);
}
#else
const char* find_first(const char* p, const char* end, const ByteSet& set) { return find_scalar(p, end, set); }
#endif

// [2] Char
bool is_xml_char(std::uint32_t cp) {
    return cp == 0x9 || cp == 0xA || cp == 0xD || (cp >= 0x20 && cp <= 0xD7FF) || (cp >= 0xE000 && cp <= 0xFFFD) ||
           (cp >= 0x10000 && cp <= 0x10FFFF);
}

// [4] NameStartChar beyond ASCII.
bool is_name_start(std::uint32_t cp) {
    return (cp >= 0xC0 && cp <= 0xD6) || (cp >= 0xD8 && cp <= 0xF6) || (cp >= 0xF8 && cp <= 0x2FF) || (cp >= 0x370 && cp <= 0x37D) ||
           (cp >= 0x37F && cp <= 0x1FFF) || (cp >= 0x200C && cp <= 0x200D) || (cp >= 0x2070 && cp <= 0x218F) ||
           (cp >= 0x2C00 && cp <= 0x2FEF) || (cp >= 0x3001 && cp <= 0xD7FF) || (cp >= 0xF900 && cp <= 0xFDCF) ||
           (cp >= 0xFDF0 && cp <= 0xFFFD) || (cp >= 0x10000 && cp <= 0xEFFFF);
}

// [4a] NameChar beyond ASCII.
bool is_name_char(std::uint32_t cp) {
    return is_name_start(cp) || cp == 0xB7 || (cp >= 0x300 && cp <= 0x36F) || (cp >= 0x203F && cp <= 0x2040);
}

// Decodes the UTF-8 sequence at p (before end); 0 bytes for an invalid one.
std::uint32_t decode_utf8(const char* p, const char* end, int& length) {
    const Byte b0 = static_cast<Byte>(p[0]);
    length = b0 < 0x80 ? 1 : b0 >= 0xF0 ? 4 : b0 >= 0xE0 ? 3 : b0 >= 0xC0 ? 2 : 0;
    if (length == 0 || end - p < length) {
        length = 0;
        return 0;
    }
    if (length == 1) return b0;
    std::uint32_t cp = b0 & (0x7F >> length);
    for (int i = 1; i < length; ++i) {
        const Byte b = static_cast<Byte>(p[i]);
        if ((b & 0xC0) != 0x80) {
            length = 0;
            return 0;
        }
        cp = (cp << 6) | (b & 0x3F);
    }
    return cp;
}

std::string code_point_name(std::uint32_t cp) {
    static const char digits[] = "0123456789ABCDEF";
    std::string hex;
    for (int shift = cp > 0xFFFF ? 20 : 12; shift >= 0; shift -= 4) hex += digits[(cp >> shift) & 0xF];
    return "U+" + hex;
}

void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

bool is_predefined_entity(std::string_view name) {
    return name == "lt" || name == "gt" || name == "amp" || name == "apos" || name == "quot";
}

std::string quoted(std::string_view text) { return "'" + excerpt(text) + "'"; }

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
    // `text` must stay alive and be followed by a NUL byte (a std::string's terminator): the
    // character-data loops stop on it without a bounds test.
    Scanner(Checker& checker, const std::string& text, const EntityScope* scope)
        : checker_(checker), begin_(text.data()), end_(text.data() + text.size()), p_(begin_), scope_(scope) {}

    bool document();
    bool walk();
    bool markup();
    bool entity_content();     // [43] content, balanced, nothing left over
    bool entity_attribute();   // no '<', references allowed in attribute values
    bool entity_declarations();  // a parameter entity used between declarations

private:
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
    Checker(const std::string& text, SourceEncoding encoding) : encoding(encoding), text_(text) {}

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

    std::optional<WellFormednessFault> run(const pugi::xml_document& parsed, const char* parse_buffer) {
        Scanner scanner(*this, text_, nullptr);
        scanner.document();
        after_root(parsed, parse_buffer);
        return std::move(fault_);
    }

    // Keeps the fault nearest to the start of the text.
    bool fail(std::size_t offset, std::string message) {
        if (!fault_ || offset < fault_->offset) fault_ = WellFormednessFault{offset, std::move(message)};
        return false;
    }

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
    int entity_depth = 0;
    std::vector<std::string_view> attributes;  // names in the current start tag
    std::unordered_set<std::string_view> attribute_set;  // the same, for tags with many attributes

private:
    // [1]: after the root element only comments, processing instructions and white space. pugixml
    // (in fragment mode) keeps text, CDATA sections and further elements there as nodes of the
    // document; their names and values lie in the parse buffer at their offsets in the text.
    void after_root(const pugi::xml_document& parsed, const char* parse_buffer) {
        const auto offset_of = [&](const char* p) {
            return p >= parse_buffer && p < parse_buffer + text_.size() ? static_cast<std::size_t>(p - parse_buffer) : text_.size();
        };
        bool root_seen = false;
        for (const pugi::xml_node n : parsed.children()) {
            const pugi::xml_node_type type = n.type();
            if (type == pugi::node_element) {
                if (root_seen) {
                    const std::size_t at = offset_of(n.name());
                    fail(at > 0 ? at - 1 : at, "a second root element " + quoted(n.name()) + "; a document has exactly one");
                    return;
                }
                root_seen = true;
            } else if (root_seen && type == pugi::node_pcdata) {
                std::size_t at = offset_of(n.value());
                while (at < text_.size() && (class_of(text_[at]) & space)) ++at;
                fail(at, "text after the root element");
                return;
            } else if (root_seen && type == pugi::node_cdata) {
                const std::size_t at = offset_of(n.value());
                fail(at >= 9 ? at - 9 : at, "a CDATA section after the root element");
                return;
            }
        }
    }

    const std::string& text_;
    std::optional<WellFormednessFault> fault_;
};

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

bool Scanner::scan_until(std::uint16_t stops) {
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

// ---- document ------------------------------------------------------------------------------

// [1] document ::= prolog element Misc*. The prolog is parsed by the grammar; from the root's
// start tag on, walk() looks only where pugixml may have let a fault through.
bool Scanner::document() {
    // [23] XMLDecl is allowed only at the very start (the byte-order mark is gone already).
    if (starts("<?xml") && (class_of(peek(5)) & space || peek(5) == '?'))
        if (!xml_declaration()) return false;
    bool doctype_seen = false;
    for (;;) {
        skip_space();
        if (at_end()) return fail(p_, "no root element");
        if (*p_ == '<' && (class_of(peek(1)) & (name_start | non_ascii))) break;
        if (!prolog_item(doctype_seen)) return false;
    }
    return walk();
}

// From the root's start tag to the end of the text. pugixml accepted the document: its tags are
// balanced, its ASCII names are XML names and every attribute is Name="value". What it lets
// through hides behind one of a few bytes (class `candidate`): a control character or 0xEF, a byte
// beyond ASCII (a name character XML does not allow), '&' (a reference), ']' (']]>'), '=' (an
// attribute: repeated, or '<' or a bad reference in its value), and '!' or '?' after '<'
// (comments, CDATA sections, processing instructions, a misplaced DOCTYPE). The walk jumps from
// one such byte to the next; a byte inside markup gets that whole construct parsed by the grammar,
// once. Every construct that may hold '<' or '>' as data starts with a candidate ('<!', '<?', or
// the '=' before an attribute value), so the nearest '<' or '>' before a candidate tells whether
// it is inside markup. Text after the root element is left to the caller (pugixml's tree has it).
// Invariant: everything before `known` is checked, and `known` lies in character data.
bool Scanner::walk() {
    const char* known = p_;
    const char* c = p_;
    while ((c = find_first(c, end_, candidate_bytes)) < end_) {
        if (class_of(*c) & check) {  // a forbidden character wherever it stands, or a harmless 0xEF
            p_ = c;
            if (!checked_character()) return false;
            c = p_;
            continue;
        }
        const char* q = c;
        while (q > known && q[-1] != '<' && q[-1] != '>') --q;
        if (q > known && q[-1] == '<') {
            p_ = q - 1;
            if (!markup()) return false;
            known = c = p_;
            continue;
        }
        p_ = c;
        if (*c == '&') {
            if (!reference(false)) return false;
        } else if (*c == ']' && starts("]]>")) {
            return fail(c, "']]>' in character data (write ]]&gt;)");
        } else {
            ++p_;  // '=', '!', '?', ']' or a byte beyond ASCII in text
        }
        known = c = p_;
    }
    p_ = end_;
    return true;
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
        return doctype();
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

// ---- DTD -----------------------------------------------------------------------------------

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

}  // namespace

std::optional<WellFormednessFault> find_well_formedness_fault(const std::string& text, SourceEncoding encoding,
                                                              const pugi::xml_document& parsed, const char* parse_buffer) {
    Checker checker(text, encoding);
    return checker.run(parsed, parse_buffer);
}

std::optional<WellFormednessFault> find_content_fault(const std::string& text) {
    Checker checker(text, SourceEncoding::utf8);
    return checker.run_content();
}

}  // namespace esi
