// The tree parser (xml/tree_parser.hpp): elements, attributes and character data of the document,
// checked and built in one pass; the rare constructs go to the well-formedness scanner's
// productions. Production numbers [n] refer to XML 1.0 (fifth edition).

#include "xml/tree_parser.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "xml/text_scan.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace esi::xml_tree {

using namespace xml_well_formed;

// ---- decoding --------------------------------------------------------------------------------

namespace {

// The character a reference at p (at '&', already checked by the scanner) stands for, appended
// to out; p is left after the ';'. A reference to an entity other than the five predefined ones
// stays as written (it is never expanded), so only its '&' is taken here.
void append_reference(const char*& p, std::string& out) {
    if (p[1] == '#') {
        const bool hex = p[2] == 'x';
        std::uint32_t value = 0;
        const char* q = p + (hex ? 3 : 2);
        for (; *q != ';'; ++q) {
            const char c = *q;
            const std::uint32_t digit = c <= '9' ? static_cast<std::uint32_t>(c - '0') : static_cast<std::uint32_t>((c | 0x20) - 'a' + 10);
            value = value * (hex ? 16 : 10) + digit;
        }
        append_utf8(out, static_cast<char32_t>(value));
        p = q + 1;
        return;
    }
    static constexpr struct {
        std::string_view spelled;
        char character;
    } predefined[] = {{"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&apos;", '\''}, {"&quot;", '"'}};
    for (const auto& entity : predefined) {
        if (std::strncmp(p, entity.spelled.data(), entity.spelled.size()) == 0) {
            out += entity.character;
            p += entity.spelled.size();
            return;
        }
    }
    out += '&';
    ++p;
}

enum class Decoding { character_data, cdata, attribute };

// [begin, end) as pugixml's parse_escapes, parse_eol and parse_wconv_attribute read it: in
// character data "\r\n" and "\r" become "\n" and references are replaced; in a CDATA section only
// the line breaks; in an attribute value every tab, line feed, carriage return and "\r\n" is one
// space ([3.3.3] attribute-value normalization) and references are replaced.
std::string decode(const char* begin, const char* end, Decoding how) {
    std::string out;
    out.reserve(static_cast<std::size_t>(end - begin));
    for (const char* p = begin; p < end;) {
        const char c = *p;
        if (c == '&' && how != Decoding::cdata) {
            append_reference(p, out);
        } else if (c == '\r') {
            out += how == Decoding::attribute ? ' ' : '\n';
            p += p + 1 < end && p[1] == '\n' ? 2 : 1;
        } else if ((c == '\n' || c == '\t') && how == Decoding::attribute) {
            out += ' ';
            ++p;
        } else {
            out += c;
            ++p;
        }
    }
    return out;
}

}  // namespace

// ---- names and bytes --------------------------------------------------------------------------

namespace {

// ASCII name characters ([4a] NameChar below U+0080) but ':', for the inner loop's name scan: a
// prefixed name ends it, and its start tag is read by start_tag(), which tells the observers.
constexpr std::array<bool, 256> make_name_chars() {
    std::array<bool, 256> t{};
    for (std::size_t b = 0; b < 256; ++b) t[b] = (classes[b] & name_char) != 0 && b != ':';
    return t;
}
constexpr std::array<bool, 256> name_chars = make_name_chars();

template <class T>
T load(const char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// The n bytes at a and b are the same (an end tag's name and its start tag's, both in the text):
// a compare or two of eight or four bytes for the names of ESI files, where memcmp is a call.
[[gnu::always_inline]] inline bool same_bytes(const char* a, const char* b, std::size_t n) {
    if (n >= 8) {
        for (std::size_t i = 0; i + 8 <= n; i += 8)
            if (load<std::uint64_t>(a + i) != load<std::uint64_t>(b + i)) return false;
        return load<std::uint64_t>(a + n - 8) == load<std::uint64_t>(b + n - 8);
    }
    if (n >= 4) return load<std::uint32_t>(a) == load<std::uint32_t>(b) && load<std::uint32_t>(a + n - 4) == load<std::uint32_t>(b + n - 4);
    for (std::size_t i = 0; i < n; ++i)
        if (a[i] != b[i]) return false;
    return true;
}

}  // namespace

// ---- the parser ------------------------------------------------------------------------------

TreeParser::TreeParser(std::string_view text, SourceEncoding encoding, Tree& tree)
    // Vendor files have lines of 25 to 40 bytes, and an element every 40 bytes or so.
    : CheckerHolder(text, encoding), Scanner(checker, text, nullptr), tree_(tree), line_starts_(text.size() / 24),
      line_start_(text.data()) {
    tree_.reserve(std::min<std::size_t>(text.size() / 32, std::size_t{1} << 16));
}

bool TreeParser::report(const char* at, std::string message) { return fail(at, std::move(message)); }

// `slow`: the start tag was read by start_tag(), which knows whether it has a prefixed name (one
// the inner loop read has none).
void TreeParser::tell_observers(std::uint32_t element, bool slow) {
    if (observer_) observer_->start_tag(tree_.element(element));
    if (prefix_observer_ && slow && tag_prefixed_) prefix_observer_->start_tag(tree_.element(element));
}

void TreeParser::count_lines(const char* from, const char* to) {
#if defined(__SSE2__)
    for (; to - from >= 16; from += 16)
        if (const unsigned mask = scan::mask_of(scan::bytes_equal(scan::load16(from), '\n'))) newlines_in_block(from, mask);
#endif
    for (; from < to; ++from)
        if (*from == '\n') newline_at(from);
}

// [3] S from p, its line feeds counted.
[[gnu::always_inline]] inline const char* TreeParser::skip_space(const char* p) {
#if defined(__SSE2__)
    while (end_ - p >= 16) {
        const __m128i v = scan::load16(p);
        const __m128i line_feed = scan::bytes_equal(v, '\n');
        const __m128i space = _mm_or_si128(_mm_or_si128(scan::bytes_equal(v, ' '), scan::bytes_equal(v, '\t')),
                                           _mm_or_si128(line_feed, scan::bytes_equal(v, '\r')));
        const unsigned other = ~scan::mask_of(space) & 0xFFFFu;
        unsigned line_feeds = scan::mask_of(line_feed);
        if (other != 0) {
            const int stop = __builtin_ctz(other);
            line_feeds &= (1u << stop) - 1;
            if (line_feeds != 0) newlines_in_block(p, line_feeds);
            return p + stop;
        }
        if (line_feeds != 0) newlines_in_block(p, line_feeds);
        p += 16;
    }
#endif
    for (; p < end_ && scan::is_space(*p); ++p)
        if (*p == '\n') newline_at(p);
    return p;
}

// The position of p on the line of line_start_. Columns count code points, from the line start
// or on from the previous position on the same line (a file written on one line, a megabyte
// long, stays linear).
SourcePos TreeParser::position_at(const char* p) {
    const auto line = line_starts_.count();
    const char* from = line_start_;
    std::uint32_t column = 0;  // 0-based, of `from`
    if (memo_line_ == line && p >= memo_ && memo_ >= from) {
        from = memo_;
        column = memo_column_;
    }
    const auto bytes = static_cast<std::size_t>(p - from);
    column += static_cast<std::uint32_t>(scan::any_beyond_ascii(from, p) ? count_code_points({from, bytes}) : bytes);
    memo_line_ = line;
    memo_ = p;
    memo_column_ = column;
    return SourcePos{line, column + 1};
}

SourcePos TreeParser::position_of(const char* p) {
    // Within the start tag just read: its line feeds are counted, so p's line is found by
    // stepping back through the latest line starts.
    std::size_t line = line_starts_.count();
    while (line > 1 && begin_ + line_starts_[line - 1] > p) --line;
    const char* from = begin_ + line_starts_[line - 1];
    const auto bytes = static_cast<std::size_t>(p - from);
    const auto column = static_cast<std::uint32_t>(scan::any_beyond_ascii(from, p) ? count_code_points({from, bytes}) : bytes);
    return SourcePos{static_cast<std::uint32_t>(line), column + 1};
}

LineStartList TreeParser::take_line_starts() { return line_starts_.take(); }

Element TreeParser::root() {
    const char* from = p_;
    const bool ok = prolog();
    count_lines(from, p_);
    if (!ok) return {};
    bool empty = false;
    root_ = start_tag(0, empty);
    if (!root_) return {};
    if (empty) tree_.node(root_).complete = true;
    return tree_.element(root_);
}

// [40] STag / [44] EmptyElemTag, p_ at '<' before a name start character. The new element's
// index, 0 after a fault.
std::uint32_t TreeParser::start_tag(std::uint32_t parent, bool& empty) {
    const char* open = p_;
    const char* q = p_ + 1;
    while (class_of(*q) & xml_well_formed::name_char) ++q;
    std::string_view element_name(open + 1, static_cast<std::size_t>(q - open - 1));
    if (class_of(*q) & non_ascii) {  // a name beyond ASCII: the scanner checks it
        p_ = open + 1;
        if (!name(element_name, "element")) return 0;
        q = p_;
    }
    tag_prefixed_ = element_name.find(':') != std::string_view::npos;
    const std::uint32_t index = tree_.add_node();
    Node& n = tree_.node(index);
    n.name = element_name;
    n.parent = parent;
    n.offset = static_cast<std::uint32_t>(open - begin_);
    n.pos = position_at(open);
    n.first_attribute = static_cast<std::uint32_t>(tree_.attributes().size());
    p_ = q;
    if (*q == '>') {
        ++p_;
        empty = false;
        return index;
    }
    if (!attributes(index, element_name, empty)) return 0;
    Node& done = tree_.node(index);
    done.attribute_count = static_cast<std::uint32_t>(tree_.attributes().size() - done.first_attribute);
    return index;
}

// The rest of a start tag after its name: attributes up to '>' or '/>' (then `empty`).
bool TreeParser::attributes(std::uint32_t element, std::string_view element_name, bool& empty) {
    const char* open = begin_ + tree_.node(element).offset;
    for (;;) {
        const char* before = p_;
        p_ = skip_space(p_);
        const char c = *p_;
        if (c == '>') {
            ++p_;
            empty = false;
            return true;
        }
        if (c == '/' && p_[1] == '>') {
            p_ += 2;
            empty = true;
            return true;
        }
        if (at_end()) return report(open, "the start tag of " + quoted(element_name) + " is not closed");
        if (!(class_of(c) & (name_start | non_ascii))) return report(open, "malformed start tag " + quoted(element_name));
        if (p_ == before) return report(p_, "whitespace expected before an attribute of " + quoted(element_name));
        if (!attribute(element, element_name)) return false;
    }
}

// [41] Attribute ::= Name Eq AttValue, and WFC: Unique Att Spec.
bool TreeParser::attribute(std::uint32_t element, std::string_view element_name) {
    const char* at = p_;
    std::string_view attribute_name;
    if (!name(attribute_name, "attribute")) return false;
    if (attribute_name.find(':') != std::string_view::npos) tag_prefixed_ = true;
    AttributeList& attributes = tree_.attributes();
    const std::size_t first = tree_.node(element).first_attribute;
    const std::size_t count = attributes.size() - first;
    // A linear search for the usual few attributes, a set for many.
    bool repeated = false;
    if (count < 16) {
        for (std::size_t i = first; i < attributes.size(); ++i) repeated = repeated || attributes[i].name == attribute_name;
    } else {
        auto& set = checker.attribute_set;
        if (count == 16) {
            set.clear();
            for (std::size_t i = first; i < attributes.size(); ++i) set.insert(attributes[i].name);
        }
        repeated = !set.insert(attribute_name).second;
    }
    if (repeated) return report(at, "attribute " + quoted(attribute_name) + " is given twice in the start tag of " + quoted(element_name));
    p_ = skip_space(p_);
    if (*p_ != '=') return report(p_, "'=' expected after attribute " + quoted(attribute_name));
    ++p_;
    p_ = skip_space(p_);
    std::string_view value;
    if (!attribute_value(attribute_name, value)) return false;
    attributes.push_back({attribute_name, value});
    if (namespace_observer_ && is_namespace_declaration(attribute_name)) namespace_observer_->declared(value);
    return true;
}

// [10] AttValue ::= '"' ([^<&"] | Reference)* '"' | "'" ([^<&'] | Reference)* "'"
bool TreeParser::attribute_value(std::string_view attribute_name, std::string_view& value) {
    const char quote = *p_;
    if (quote != '"' && quote != '\'') return report(p_, "the value of attribute " + quoted(attribute_name) + " must be quoted");
    const char* quote_at = p_;
    const char* start = ++p_;
    bool decoded = false;
    for (;;) {
        p_ = scan::value_stop(p_, end_, quote);
        if (at_end()) return report(quote_at, "the value of attribute " + quoted(attribute_name) + " is not closed");
        const char c = *p_;
        if (c == quote) break;
        if (c == '<') return report(p_, "'<' inside the value of attribute " + quoted(attribute_name) + " (write &lt;)");
        if (c == '&') {
            if (!reference(true)) return false;
            decoded = true;
        } else if (c == '\t' || c == '\n' || c == '\r') {
            if (c == '\n') newline_at(p_);
            decoded = true;
            ++p_;
        } else if (!checked_character()) {
            return false;
        }
    }
    value = decoded ? tree_.keep(decode(start, p_, Decoding::attribute)) : std::string_view(start, static_cast<std::size_t>(p_ - start));
    ++p_;
    return true;
}

// [42] ETag ::= '</' Name S? '>', p_ at '<'; it must close `element`.
bool TreeParser::end_tag(std::uint32_t element) {
    const char* open = p_;
    const char* name_at = p_ + 2;
    const Node& n = tree_.node(element);
    const std::size_t length = n.name.size();
    if (static_cast<std::size_t>(end_ - name_at) > length && same_bytes(name_at, n.name.data(), length)) {
        const char* q = name_at + length;
        if (*q == '>') {
            p_ = q + 1;
            tree_.node(element).complete = true;
            return true;
        }
        if (!(class_of(*q) & (name_char | non_ascii))) {
            p_ = skip_space(q);
            if (*p_ != '>') return report(open, "malformed end tag " + quoted(n.name));
            ++p_;
            tree_.node(element).complete = true;
            return true;
        }
    }
    p_ = name_at;
    std::string_view found;
    if (!name(found, "end tag")) return false;
    return report(name_at, "end tag " + quoted(found) + " does not match the start tag " + quoted(n.name) + " on line " +
                               std::to_string(n.pos.line));
}

bool TreeParser::unclosed(std::uint32_t element) {
    const Node& n = tree_.node(element);
    return report(end_, "the document ends inside element " + quoted(n.name) + " (its start tag is on line " +
                            std::to_string(n.pos.line) + ")");
}

inline void TreeParser::append_child(std::uint32_t parent, std::uint32_t* last_child, std::uint32_t child) {
    if (*last_child != 0) tree_.node(*last_child).next_sibling = child;
    else tree_.node(parent).first_child = child;
    *last_child = child;
}

// [14] CharData and [67] Reference in [43] content, from `start` up to the next '<'; p_ is past
// the white space at its start, at a byte that is not '<'.
bool TreeParser::character_data(const char* start, std::uint32_t owner, std::uint32_t* last_child, bool decoded) {
    for (;;) {
        p_ = scan::text_stop(p_, end_);
        if (at_end() || *p_ == '<') break;
        const char c = *p_;
        if (c == '\n') {
            newline_at(p_);
            ++p_;
        } else if (c == '&') {
            if (!reference(false)) return false;
            decoded = true;
        } else if (c == '\r') {
            decoded = true;
            ++p_;
        } else if (c == ']') {
            if (p_[1] == ']' && p_[2] == '>') return report(p_, "']]>' in character data (write ]]&gt;)");
            ++p_;
        } else if (!checked_character()) {
            return false;
        }
    }
    if (owner != 0) keep_text(start, p_, decoded, owner, last_child);
    return true;
}

// Character data that is not only white space, kept under `owner`: as its own text when it has
// no child yet (pugixml's parse_embed_pcdata), else as a pcdata child.
void TreeParser::keep_text(const char* start, const char* stop, bool decoded, std::uint32_t owner, std::uint32_t* last_child) {
    const std::string_view text =
        decoded ? tree_.keep(decode(start, stop, Decoding::character_data)) : std::string_view(start, static_cast<std::size_t>(stop - start));
    Node& o = tree_.node(owner);
    if (!o.has_value && o.first_child == 0) {
        o.value = text;
        o.has_value = true;
        return;
    }
    const std::uint32_t index = tree_.add_node();
    Node& n = tree_.node(index);
    n.kind = NodeKind::pcdata;
    n.value = text;
    n.parent = owner;
    n.offset = static_cast<std::uint32_t>(start - begin_);
    n.complete = true;
    append_child(owner, last_child, index);
}

bool TreeParser::other_markup(std::uint32_t owner, std::uint32_t* last_child) {
    if (p_[1] == '?') return scanned(&TreeParser::processing_instruction);
    if (starts("<!--")) return scanned(&TreeParser::comment);
    if (starts("<![CDATA[")) {
        const char* start = p_ + 9;
        if (!scanned(&TreeParser::cdata_section)) return false;
        if (owner == 0) return true;
        const char* end = p_ - 3;
        const std::string_view content(start, static_cast<std::size_t>(end - start));
        const std::uint32_t index = tree_.add_node();
        Node& n = tree_.node(index);
        n.kind = NodeKind::cdata;
        n.value = content.find('\r') == std::string_view::npos ? content : tree_.keep(decode(start, end, Decoding::cdata));
        n.parent = owner;
        n.offset = static_cast<std::uint32_t>(start - begin_);
        n.complete = true;
        append_child(owner, last_child, index);
        return true;
    }
    if (starts("<!DOCTYPE")) return report(p_, "a DOCTYPE is only allowed before the root element");
    return report(p_, "markup declaration outside the DOCTYPE");
}

// Character data from p up to the next '<', in blocks of 16 bytes: each block is compared once
// for '<', white space, line feeds, carriage returns and what needs a closer look ('&', ']' of
// "]]>", control characters XML forbids, 0xEF of U+FFFE/FFFF). Most runs of an ESI file are
// indentation or a short value and end in their first block.
[[gnu::always_inline]] inline TreeParser::Run TreeParser::run_to_markup(const char* p) {
    Run run;
#if defined(__SSE2__)
    const __m128i forbidden_limit = _mm_set1_epi8(0x1F);
    while (end_ - p >= 16) {
        const __m128i v = scan::load16(p);
        const __m128i tab = scan::bytes_equal(v, '\t');
        const __m128i line_feed = scan::bytes_equal(v, '\n');
        const __m128i carriage_return = scan::bytes_equal(v, '\r');
        const __m128i breaks = _mm_or_si128(line_feed, carriage_return);
        const __m128i control = _mm_cmpeq_epi8(_mm_min_epu8(v, forbidden_limit), v);  // every byte below ' '
        const __m128i look = _mm_or_si128(_mm_andnot_si128(_mm_or_si128(tab, breaks), control),
                                          _mm_or_si128(_mm_or_si128(scan::bytes_equal(v, '&'), scan::bytes_equal(v, ']')),
                                                       scan::bytes_equal(v, static_cast<char>(0xEF))));
        const __m128i space = _mm_or_si128(_mm_or_si128(scan::bytes_equal(v, ' '), tab), breaks);
        const unsigned markup = scan::mask_of(scan::bytes_equal(v, '<'));
        const unsigned before = markup != 0 ? (markup & (0u - markup)) - 1 : 0xFFFFu;  // the bytes before the first '<'
        if (scan::mask_of(look) & before) {
            run.stop = p;  // the caller reads this block on byte by byte
            run.plain = false;
            return run;
        }
        if (const unsigned feeds = scan::mask_of(line_feed) & before) newlines_in_block(p, feeds);
        run.white = run.white && (~scan::mask_of(space) & before) == 0;
        run.carriage_return = run.carriage_return || (scan::mask_of(carriage_return) & before) != 0;
        if (markup != 0) {
            run.stop = p + __builtin_ctz(markup);
            return run;
        }
        p += 16;
    }
#endif
    run.stop = p;
    run.plain = false;
    return run;
}

// The two runs of character data an ESI file is made of, without a look at each class of byte:
// a line break and indentation before a tag, and a short value ("#x1A00", "Status word") before
// an end tag. True when `p` stood at one; p is then at the '<' after it, and a value is kept
// under `owner`. Needs 32 bytes of text after p.
[[gnu::always_inline]] inline bool TreeParser::short_run(const char*& p, const char*& text, std::uint32_t owner,
                                                          std::uint32_t* last_child) {
#if defined(__SSE2__)
    const char first = *p;
    if (first == '\n' || first == '\r') {
        const char* line_feed = p + (first == '\r');
        if (*line_feed != '\n') return false;
        const char* indentation = line_feed + 1;
        for (;;) {  // spaces and tabs, 16 bytes a step
            if (end_ - indentation < 16) return false;
            const __m128i v = scan::load16(indentation);
            const unsigned other = ~scan::mask_of(_mm_or_si128(scan::bytes_equal(v, ' '), scan::bytes_equal(v, '\t'))) & 0xFFFFu;
            if (other != 0) {
                indentation += __builtin_ctz(other);
                break;
            }
            indentation += 16;
        }
        if (*indentation != '<') return false;
        newline_at(line_feed);
        p = indentation;
        return true;
    }
    if (static_cast<unsigned char>(first) <= ' ') return false;
    const char* const stop = scan::short_plain_text_end(p);
    if (!stop) return false;
    Node& o = tree_.node(owner);
    if (!o.has_value && o.first_child == 0) {
        o.value = std::string_view(p, static_cast<std::size_t>(stop - p));
        o.has_value = true;
    } else {
        keep_text(p, stop, false, owner, last_child);
    }
    p = text = stop;
    return true;
#else
    (void)p, (void)text, (void)owner, (void)last_child;
    return false;
#endif
}

// The rest of a leaf whose start tag ends before p: a short value (or none) and the end tag
// "</name>", with nothing in the value that needs a closer look. True when p stood at one; p is
// then after its end tag and the element is complete. Needs 32 bytes of text after p.
[[gnu::always_inline]] inline bool TreeParser::leaf(const char*& p, std::uint32_t element, std::string_view name) {
#if defined(__SSE2__)
    const char* stop = p;
    if (*p != '<') {
        if (static_cast<unsigned char>(*p) <= ' ') return false;  // white space first: the general way
        stop = scan::short_plain_text_end(p);
        if (!stop) return false;
    }
    const std::size_t length = name.size();
    const char* end_name = stop + 2;
    if (stop[1] != '/' || static_cast<std::size_t>(end_ - end_name) <= length || end_name[length] != '>' ||
        !same_bytes(end_name, name.data(), length))
        return false;
    Node& n = tree_.node(element);
    if (stop != p) {
        n.value = std::string_view(p, static_cast<std::size_t>(stop - p));
        n.has_value = true;
    }
    n.complete = true;
    p = end_name + length + 1;
    return true;
#else
    (void)p, (void)element, (void)name;
    return false;
#endif
}

// The attributes of a start tag from q, the byte after its name, to its '>' or "/>", when they
// are written as nearly all attributes of ESI files are: spaces before each, an ASCII name
// without a prefix, '=' and a quoted value with nothing in it to decode or look at closely, at
// most max_plain_attributes of them, none given twice. False for anything else (nothing is
// then kept, and start_tag() reads the tag): its checks and reports stay in one place. A
// namespace declaration is left to start_tag() while someone listens for them.
bool TreeParser::plain_attributes(const char* q, PlainAttributes& out) const {
    for (;;) {
        if (*q != ' ') return false;
        do ++q;
        while (*q == ' ');
        if ((class_of(*q) & (name_start | non_ascii)) != name_start || *q == ':') {
            if (*q == '>' && out.count > 0) {  // white space before the end of the tag
                out.after = q + 1;
                return true;
            }
            if (*q == '/' && q[1] == '>' && out.count > 0) {
                out.empty = true;
                out.after = q + 2;
                return true;
            }
            return false;
        }
        const char* name_at = q;
        while (name_chars[static_cast<Byte>(*q)]) ++q;  // the text ends with a NUL, which ends this
        const std::string_view name(name_at, static_cast<std::size_t>(q - name_at));
        if (q[0] != '=' || (q[1] != '"' && q[1] != '\'')) return false;
        if (namespace_observer_ && name.starts_with("xmlns")) return false;
        if (out.count == max_plain_attributes) return false;
        for (unsigned i = 0; i < out.count; ++i)
            if (out.items[i].name == name) return false;  // given twice: start_tag() says so
        const char quote = q[1];
        const char* value_at = q + 2;
        q = scan::value_stop(value_at, end_, quote);
        if (q == end_ || *q != quote) return false;
        out.items[out.count++] = {name, std::string_view(value_at, static_cast<std::size_t>(q - value_at))};
        ++q;
        if (*q == '>') {
            out.after = q + 1;
            return true;
        }
        if (*q == '/' && q[1] == '>') {
            out.empty = true;
            out.after = q + 2;
            return true;
        }
    }
}

// The inner loop of the parse: an element's content, its children's and theirs, built into the
// tree. The steps nearly every element of a file takes (a run of white space or a short value, a
// start tag without attributes, an end tag) are inline here, on a local cursor; everything else is
// handed to the functions above, through p_.
bool TreeParser::expand(Element element) {
    const std::uint32_t top_index = element.index();
    if (tree_.node(top_index).complete) return true;
    if (faulted()) return false;
    building_.clear();
    building_.push_back({top_index, 0});
    const char* p = p_;
    const char* const end = end_;
    // The short runs and leaves read up to 32 bytes ahead without a bound test.
    const char* const roomy = end - std::min<std::ptrdiff_t>(32, end - begin_);
    for (;;) {
        Open* top = &building_.back();
        const char* text = p;
        if (*p != '<' && !(p < roomy && short_run(p, text, top->index, &top->last_child))) {
            const Run run = run_to_markup(p);
            p = run.stop;
            if (run.plain) {
                if (!run.white) {
                    keep_text(text, p, run.carriage_return, top->index, &top->last_child);
                    text = p;  // what precedes the '<' on its line is not all white space
                }
            } else {  // near the end of the text, or a byte to look at closely: byte by byte
                p_ = p;
                if (run.white) p_ = skip_space(p_);
                if (*p_ != '<' && !at_end()) {
                    if (!character_data(text, top->index, &top->last_child, run.carriage_return)) return false;
                    text = p_;
                }
                p = p_;
                if (p >= end) return unclosed(top->index);
            }
        }
        const char next = p[1];
        if (next == '/') {
            const Node& open = tree_.node(top->index);
            const char* name_at = p + 2;
            const std::size_t length = open.name.size();
            if (static_cast<std::size_t>(end - name_at) > length && name_at[length] == '>' &&
                same_bytes(name_at, open.name.data(), length)) {
                p = name_at + length + 1;
                tree_.node(top->index).complete = true;
            } else {
                p_ = p;
                if (!end_tag(top->index)) return false;
                p = p_;
            }
            building_.pop_back();
            if (building_.empty()) {
                p_ = p;
                return true;
            }
            continue;
        }
        if (!(class_of(next) & (name_start | non_ascii))) {
            p_ = p;
            if (next == '!' || next == '?') {
                if (!other_markup(top->index, &top->last_child)) return false;
                p = p_;
                continue;
            }
            return report(p, "'<' that starts no tag (write &lt; for a less-than sign)");
        }
        // A start tag.
        const std::uint32_t parent = top->index;
        std::uint32_t child = 0;
        bool empty = false;
        const char* q = p + 1;
        while (name_chars[static_cast<Byte>(q[0])] && name_chars[static_cast<Byte>(q[1])]) q += 2;  // two bytes a step
        q += name_chars[static_cast<Byte>(*q)];
        if (*q == '>') {  // nearly every start tag of an ESI file: an ASCII name, no attribute
            // After a line feed in the white space before it, the tag's column is its distance
            // from the line start, which white space alone separates from it.
            const SourcePos pos = line_start_ > text ? SourcePos{line_starts_.count(), static_cast<std::uint32_t>(p - line_start_) + 1}
                                                     : position_at(p);
            const std::string_view name(p + 1, static_cast<std::size_t>(q - p - 1));
            child = tree_.add_element(name, parent, static_cast<std::uint32_t>(p - begin_), pos);
            p = q + 1;
            // A leaf, "<Name>value</Name>" as most elements of an ESI file are, is read to its end
            // tag right here and never goes on the stack.
            if (p < roomy && leaf(p, child, name)) {
                append_child(parent, &top->last_child, child);
                if (observer_) {
                    p_ = p;
                    tell_observers(child, false);
                }
                continue;
            }
        } else if (PlainAttributes plain; *q == ' ' && plain_attributes(q, plain)) {
            const SourcePos pos = line_start_ > text ? SourcePos{line_starts_.count(), static_cast<std::uint32_t>(p - line_start_) + 1}
                                                     : position_at(p);
            const std::string_view name(p + 1, static_cast<std::size_t>(q - p - 1));
            AttributeList& attributes = tree_.attributes();
            child = tree_.add_element(name, parent, static_cast<std::uint32_t>(p - begin_), pos, static_cast<std::uint32_t>(attributes.size()));
            attributes.insert(attributes.end(), plain.items, plain.items + plain.count);
            tree_.node(child).attribute_count = plain.count;
            tag_prefixed_ = false;
            empty = plain.empty;
            p = plain.after;
            q = p - 1;  // at the '>': the tag was not read by start_tag()
            if (!empty && p < roomy && leaf(p, child, name)) {
                append_child(parent, &top->last_child, child);
                if (observer_) {
                    p_ = p;
                    tell_observers(child, false);
                }
                continue;
            }
        } else {
            p_ = p;
            child = start_tag(parent, empty);
            if (child == 0) return false;
            p = p_;
        }
        append_child(parent, &top->last_child, child);
        if (empty) tree_.node(child).complete = true;
        else building_.push_back({child, 0});
        // start_tag() read it when the name scan did not end at '>'; only then can it be prefixed.
        const bool slow = *q != '>';
        if (observer_ || (slow && prefix_observer_ && tag_prefixed_)) {
            p_ = p;
            tell_observers(child, slow);
        }
    }
}

Element TreeParser::next_child(Element parent) {
    const std::uint32_t index = parent.index();
    if (faulted() || tree_.node(index).complete) return {};
    for (;;) {
        const char* text = p_;
        p_ = skip_space(p_);
        if (*p_ != '<' && !at_end() && !character_data(text, 0, nullptr)) return {};
        if (at_end()) {
            unclosed(index);
            return {};
        }
        const char next = p_[1];
        if (next == '/') {
            end_tag(index);
            return {};
        }
        if (class_of(next) & (name_start | non_ascii)) {
            bool empty = false;
            const std::uint32_t child = start_tag(index, empty);
            if (child == 0) return {};
            if (empty) tree_.node(child).complete = true;
            tell_observers(child, true);
            return tree_.element(child);
        }
        if (next == '!' || next == '?') {
            if (!other_markup(0, nullptr)) return {};
            continue;
        }
        report(p_, "'<' that starts no tag (write &lt; for a less-than sign)");
        return {};
    }
}

// [1] document ::= prolog element Misc*: after the root element only comments, processing
// instructions and white space.
bool TreeParser::finish() {
    if (faulted() || root_ == 0) return false;
    if (!stream_children(tree_.element(root_), [](Element, std::string_view, std::string_view) {})) return false;
    for (;;) {
        p_ = skip_space(p_);
        if (at_end()) return true;
        if (*p_ != '<') {
            if (scan::needs_check(*p_) && !checked_character()) return false;
            return report(p_, "text after the root element");
        }
        const char next = p_[1];
        bool ok = true;
        if (next == '?') ok = scanned(&TreeParser::processing_instruction);
        else if (starts("<!--")) ok = scanned(&TreeParser::comment);
        else if (starts("<![CDATA[")) ok = report(p_, "a CDATA section after the root element");
        else if (next == '!') ok = other_markup(0, nullptr);  // a DOCTYPE or a declaration: misplaced
        else if (next == '/') {
            const char* name_at = p_ + 2;
            p_ = name_at;
            std::string_view found;
            ok = name(found, "end tag") && report(name_at, "end tag " + quoted(found) + " without a start tag");
        } else if (class_of(next) & (name_start | non_ascii)) {
            const char* open = p_++;
            std::string_view found;
            ok = name(found, "element") && report(open, "a second root element " + quoted(found) + "; a document has exactly one");
        } else {
            ok = report(p_, "'<' that starts no tag (write &lt; for a less-than sign)");
        }
        if (!ok) return false;
    }
}

std::optional<TreeParser::Doctype> TreeParser::doctype_declaration() const {
    if (!checker.doctype_seen) return std::nullopt;
    const std::string_view declaration(begin_ + checker.doctype_begin, checker.doctype_end - checker.doctype_begin);
    return Doctype{checker.doctype_begin, declaration.find("<!ENTITY") != std::string_view::npos};
}

}  // namespace esi::xml_tree

namespace esi {

std::optional<WellFormednessFault> find_well_formedness_fault(const std::string& text, SourceEncoding encoding) {
    xml_tree::Tree tree;
    xml_tree::TreeParser parser(text, encoding, tree);
    if (parser.root()) parser.finish();
    return parser.fault();
}

}  // namespace esi
