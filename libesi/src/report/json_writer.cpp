#include "report/json_writer.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <charconv>

namespace esi::report {

void JsonWriter::indent() { out_.append(2 * counts_.size(), ' '); }

void JsonWriter::before_value() {
    if (after_key_) {
        after_key_ = false;
        return;
    }
    if (counts_.empty()) return;  // the top-level value
    out_ += counts_.back()++ == 0 ? "\n" : ",\n";
    indent();
}

void JsonWriter::key(std::string_view name) {
    out_ += counts_.back()++ == 0 ? "\n" : ",\n";
    indent();
    escaped(name);
    out_ += ": ";
    after_key_ = true;
}

void JsonWriter::open(char bracket) {
    before_value();
    out_ += bracket;
    counts_.push_back(0);
}

void JsonWriter::close(char bracket) {
    const bool empty = counts_.back() == 0;
    counts_.pop_back();
    if (!empty) {
        out_ += '\n';
        indent();
    }
    out_ += bracket;
}

void JsonWriter::value(std::string_view text) {
    before_value();
    escaped(text);
}

void JsonWriter::value(std::uint64_t number) {
    before_value();
    char digits[24];
    const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, number);
    out_.append(digits, end);
}

void JsonWriter::null() {
    before_value();
    out_ += "null";
}

namespace {

constexpr std::string_view replacement = "\xEF\xBF\xBD";  // U+FFFD

// The number of continuation bytes after a lead byte, and the range its first continuation byte
// must lie in (no overlong forms, no surrogates, nothing above U+10FFFF); 0 continuation bytes
// for a byte that starts no sequence.
struct Lead {
    int continuation;
    unsigned char low;
    unsigned char high;
};

Lead lead_of(unsigned char b) {
    if (b >= 0xC2 && b <= 0xDF) return {1, 0x80, 0xBF};
    if (b == 0xE0) return {2, 0xA0, 0xBF};
    if ((b >= 0xE1 && b <= 0xEC) || b == 0xEE || b == 0xEF) return {2, 0x80, 0xBF};
    if (b == 0xED) return {2, 0x80, 0x9F};
    if (b == 0xF0) return {3, 0x90, 0xBF};
    if (b >= 0xF1 && b <= 0xF3) return {3, 0x80, 0xBF};
    if (b == 0xF4) return {3, 0x80, 0x8F};
    return {0, 0, 0};
}

}  // namespace

// As nlohmann's serializer: the escapes of JSON for '"', '\\' and control characters (\u00XX in
// lower-case hex where JSON has no short form), everything else as written. A byte that breaks a
// UTF-8 sequence replaces the sequence so far with U+FFFD and is read again as the start of the
// next one; a byte that starts none is replaced itself; a sequence cut off by the end is replaced.
void JsonWriter::escaped(std::string_view text) {
    out_ += '"';
    std::size_t i = 0;
    const std::size_t n = text.size();
    while (i < n) {
        // Runs that need no escape, copied at once; found 16 bytes a step where SSE2 is there
        // (diagnostic messages and paths are mostly long plain ASCII).
        std::size_t run = i;
#if defined(__SSE2__)
        while (n - run >= 16) {
            const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(text.data() + run));
            const __m128i control = _mm_cmpeq_epi8(_mm_min_epu8(v, _mm_set1_epi8(0x1F)), v);
            const __m128i special = _mm_or_si128(_mm_cmpeq_epi8(v, _mm_set1_epi8('"')), _mm_cmpeq_epi8(v, _mm_set1_epi8('\\')));
            // The sign bits are the bytes from 0x80 on.
            const unsigned stop = static_cast<unsigned>(_mm_movemask_epi8(_mm_or_si128(control, special)) | _mm_movemask_epi8(v));
            if (stop != 0) {
                run += static_cast<std::size_t>(__builtin_ctz(stop));
                break;
            }
            run += 16;
        }
#endif
        while (run < n) {
            const auto c = static_cast<unsigned char>(text[run]);
            if (c < 0x20 || c == '"' || c == '\\' || c >= 0x80) break;
            ++run;
        }
        out_.append(text.data() + i, run - i);
        i = run;
        if (i == n) break;
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            switch (c) {
                case '"': out_ += "\\\""; break;
                case '\\': out_ += "\\\\"; break;
                case '\b': out_ += "\\b"; break;
                case '\t': out_ += "\\t"; break;
                case '\n': out_ += "\\n"; break;
                case '\f': out_ += "\\f"; break;
                case '\r': out_ += "\\r"; break;
                default: {
                    static constexpr char hex[] = "0123456789abcdef";
                    out_ += "\\u00";
                    out_ += hex[c >> 4];
                    out_ += hex[c & 15];
                }
            }
            ++i;
            continue;
        }
        const Lead lead = lead_of(c);
        if (lead.continuation == 0) {  // starts no sequence: replaced, and consumed
            out_ += replacement;
            ++i;
            continue;
        }
        std::size_t k = 1;
        bool broken = false;
        for (; k <= static_cast<std::size_t>(lead.continuation); ++k) {
            if (i + k >= n) break;
            const auto b = static_cast<unsigned char>(text[i + k]);
            const bool ok = k == 1 ? (b >= lead.low && b <= lead.high) : (b >= 0x80 && b <= 0xBF);
            if (!ok) {
                broken = true;
                break;
            }
        }
        if (broken || i + k > n || k <= static_cast<std::size_t>(lead.continuation)) {
            // The bytes read so far are replaced; the breaking byte (or the end) comes next.
            out_ += replacement;
            i += k;
            continue;
        }
        out_.append(text.data() + i, k);
        i += k;
    }
    out_ += '"';
}

}  // namespace esi::report
