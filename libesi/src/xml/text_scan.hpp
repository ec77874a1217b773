#pragma once
// The byte searches of the tree parser's inner loops (xml/tree_parser.cpp), 16 bytes per step with
// SSE2 (every x86-64 processor has it) and a byte at a time elsewhere and for the last bytes of a
// text. Each returns the first byte at or after `p` that the parser must look at, or `end`; `end`
// points at the NUL after the text, which every search stops at.
//
// Vendor files are 40 % indentation and their character data is short (a name, a number), so a
// search mostly ends in its first block: what matters is that a block costs a few instructions.

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace esi::xml_tree::scan {

[[gnu::always_inline]] inline bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }

// A control character XML 1.0 forbids ([2] Char: only tab, line feed and carriage return below
// U+0020), or 0xEF, the lead byte of U+FFFE and U+FFFF (the text is valid UTF-8 already).
[[gnu::always_inline]] inline bool needs_check(char c) {
    const auto b = static_cast<unsigned char>(c);
    return (b < 0x20 && b != '\t' && b != '\n' && b != '\r') || b == 0xEF;
}

#if defined(__SSE2__)
[[gnu::always_inline]] inline __m128i load16(const char* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); }
[[gnu::always_inline]] inline __m128i bytes_equal(__m128i v, char c) { return _mm_cmpeq_epi8(v, _mm_set1_epi8(c)); }
[[gnu::always_inline]] inline unsigned mask_of(__m128i v) { return static_cast<unsigned>(_mm_movemask_epi8(v)); }

// Bytes that are a control character XML forbids, or 0xEF.
[[gnu::always_inline]] inline __m128i check_bytes(__m128i v) {
    const __m128i control = _mm_cmpeq_epi8(_mm_min_epu8(v, _mm_set1_epi8(0x1F)), v);  // v <= 0x1F
    const __m128i allowed = _mm_or_si128(_mm_or_si128(bytes_equal(v, '\t'), bytes_equal(v, '\n')), bytes_equal(v, '\r'));
    return _mm_or_si128(_mm_andnot_si128(allowed, control), bytes_equal(v, static_cast<char>(0xEF)));
}

// The '<' that ends a short text at p, within its first 16 bytes, when nothing before it needs a
// closer look (a control character, line breaks and tabs included, '&', ']' or 0xEF); null when
// there is none. Needs 16 bytes of text at p.
[[gnu::always_inline]] inline const char* short_plain_text_end(const char* p) {
    const __m128i v = load16(p);
    const unsigned markup = mask_of(bytes_equal(v, '<'));
    if (markup == 0) return nullptr;
    const __m128i control = _mm_cmpeq_epi8(_mm_min_epu8(v, _mm_set1_epi8(0x1F)), v);
    const __m128i look =
        _mm_or_si128(_mm_or_si128(control, bytes_equal(v, '&')), _mm_or_si128(bytes_equal(v, ']'), bytes_equal(v, static_cast<char>(0xEF))));
    if (mask_of(look) & ((markup & (0u - markup)) - 1)) return nullptr;  // a byte to look at before the first '<'
    return p + __builtin_ctz(markup);
}
#endif

// The first byte that is not XML white space ([3] S).
[[gnu::always_inline]] inline const char* skip_space(const char* p, const char* end) {
#if defined(__SSE2__)
    while (end - p >= 16) {
        const __m128i v = load16(p);
        const __m128i space = _mm_or_si128(_mm_or_si128(bytes_equal(v, ' '), bytes_equal(v, '\t')),
                                           _mm_or_si128(bytes_equal(v, '\n'), bytes_equal(v, '\r')));
        const unsigned other = ~mask_of(space) & 0xFFFFu;
        if (other != 0) return p + __builtin_ctz(other);
        p += 16;
    }
#endif
    while (p < end && is_space(*p)) ++p;
    return p;
}

// In character data: '<', '&', ']' (of "]]>"), '\r' (read as a line feed), '\n' (counted) and
// needs_check().
[[gnu::always_inline]] inline const char* text_stop(const char* p, const char* end) {
#if defined(__SSE2__)
    while (end - p >= 16) {
        const __m128i v = load16(p);
        const __m128i markup = _mm_or_si128(_mm_or_si128(bytes_equal(v, '<'), bytes_equal(v, '&')),
                                            _mm_or_si128(bytes_equal(v, ']'), bytes_equal(v, '\r')));
        const unsigned stops = mask_of(_mm_or_si128(_mm_or_si128(markup, bytes_equal(v, '\n')), check_bytes(v)));
        if (stops != 0) return p + __builtin_ctz(stops);
        p += 16;
    }
#endif
    while (p < end && *p != '<' && *p != '&' && *p != ']' && *p != '\r' && *p != '\n' && !needs_check(*p)) ++p;
    return p;
}

// In an attribute value quoted with `quote`: the quote, '<', '&', a tab or line break (read as a
// space) and needs_check().
[[gnu::always_inline]] inline const char* value_stop(const char* p, const char* end, char quote) {
#if defined(__SSE2__)
    while (end - p >= 16) {
        const __m128i v = load16(p);
        const __m128i control = _mm_cmpeq_epi8(_mm_min_epu8(v, _mm_set1_epi8(0x1F)), v);  // every byte below ' '
        const __m128i markup = _mm_or_si128(_mm_or_si128(bytes_equal(v, quote), bytes_equal(v, '<')),
                                            _mm_or_si128(bytes_equal(v, '&'), bytes_equal(v, static_cast<char>(0xEF))));
        const unsigned stops = mask_of(_mm_or_si128(markup, control));
        if (stops != 0) return p + __builtin_ctz(stops);
        p += 16;
    }
#endif
    while (p < end && *p != quote && *p != '<' && *p != '&' && static_cast<unsigned char>(*p) >= 0x20 &&
           static_cast<unsigned char>(*p) != 0xEF)
        ++p;
    return p;
}

// Whether [p, end) holds a byte beyond ASCII, eight bytes at a time.
inline bool any_beyond_ascii(const char* p, const char* end) {
    std::uint64_t any = 0;
    for (; end - p >= 8; p += 8) {
        std::uint64_t v;
        std::memcpy(&v, p, 8);
        any |= v;
    }
    for (; p < end; ++p) any |= static_cast<unsigned char>(*p);
    return (any & 0x8080808080808080ull) != 0;
}

}  // namespace esi::xml_tree::scan
