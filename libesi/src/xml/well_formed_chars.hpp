#pragma once
// Byte and character classes of the XML 1.0 well-formedness check (well_formed.cpp): the byte-class
// table, byte sets searched 32 bytes at a time, and the Char/Name productions beyond ASCII with
// their UTF-8 helpers. The class lookups and the searches run for nearly every byte of a document,
// so they are defined here, where every file of the check inlines them; the rest is out of line in
// well_formed_chars.cpp.

#include <array>
#include <cstdint>
#include <string>

namespace esi::xml_well_formed {

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

inline constexpr std::array<std::uint16_t, 256> classes = make_classes();

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
inline constexpr std::uint16_t value_stops = quot | apos | lt | amp | check;
inline constexpr ByteSet candidate_bytes = make_byte_set(classes, candidate);
inline constexpr ByteSet value_stop_bytes = make_byte_set(classes, value_stops);
static_assert(holds_exactly(candidate_bytes, classes, candidate));
static_assert(holds_exactly(value_stop_bytes, classes, value_stops));

// The first byte of `set` in [p, end), or end.
inline const char* find_scalar(const char* p, const char* end, const ByteSet& set) {
    while (p < end && !set.contains(static_cast<Byte>(*p))) ++p;
    return p;
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same, 32 bytes per step (well_formed_chars.cpp).
[[gnu::target("avx2")]] const char* find_avx2(const char* p, const char* end, const ByteSet& set);

inline const char* find_first(const char* p, const char* end, const ByteSet& set) {
    static const auto find = __builtin_cpu_supports("avx2") ? find_avx2 : find_scalar;
    return find(p, end, set);
}
#else
inline const char* find_first(const char* p, const char* end, const ByteSet& set) { return find_scalar(p, end, set); }
#endif

// [2] Char
inline bool is_xml_char(std::uint32_t cp) {
    return cp == 0x9 || cp == 0xA || cp == 0xD || (cp >= 0x20 && cp <= 0xD7FF) || (cp >= 0xE000 && cp <= 0xFFFD) ||
           (cp >= 0x10000 && cp <= 0x10FFFF);
}

// [4] NameStartChar beyond ASCII.
bool is_name_start(std::uint32_t cp);

// [4a] NameChar beyond ASCII.
bool is_name_char(std::uint32_t cp);

// Decodes the UTF-8 sequence at p (before end); 0 bytes for an invalid one.
std::uint32_t decode_utf8(const char* p, const char* end, int& length);

// "U+0000" .. "U+10FFFF", for messages.
std::string code_point_name(std::uint32_t cp);

}  // namespace esi::xml_well_formed
