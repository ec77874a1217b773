// Byte and character classes of the XML 1.0 well-formedness check: the out-of-line half of
// well_formed_chars.hpp.

#include "xml/well_formed_chars.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace esi::xml_well_formed {

#if defined(__x86_64__) && defined(__GNUC__)
// find_scalar, 32 bytes per step: both nibbles of every byte are looked up at once (vpshufb) and
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
#endif

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

}  // namespace esi::xml_well_formed
