#pragma once
// Numbers as ESI writes them: HexDecValue is decimal or "#x" hex (ETG.2000 schema); "0x" hex is
// not valid ESI but is accepted with a diagnostic because real files contain it.

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace esi {

// The value of each byte as a hex digit, 0xFF for a byte that is none: one lookup per digit (a
// decimal digit is one whose value is below 10). Every reader of numbers and hex data uses it.
inline constexpr std::array<std::uint8_t, 256> hex_digit_values = [] {
    std::array<std::uint8_t, 256> values{};
    for (auto& v : values) v = 0xFF;
    for (int c = '0'; c <= '9'; ++c) values[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(c - '0');
    for (int c = 'a'; c <= 'f'; ++c) values[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(c - 'a' + 10);
    for (int c = 'A'; c <= 'F'; ++c) values[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(c - 'A' + 10);
    return values;
}();

// A signed 65-bit value: ESI defaults reach 2^64-1 (ULINT) and go down to -2^63 (LINT).
struct Number {
    std::uint64_t magnitude = 0;
    bool negative = false;

    [[nodiscard]] static constexpr Number from_signed(std::int64_t v) {
        return v < 0 ? Number{static_cast<std::uint64_t>(-(v + 1)) + 1u, true} : Number{static_cast<std::uint64_t>(v), false};
    }
    [[nodiscard]] static constexpr Number from_unsigned(std::uint64_t v) { return Number{v, false}; }

    // Inline: the reader converts every number it reads.
    [[nodiscard]] std::optional<std::int64_t> as_int64() const {
        constexpr auto max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
        if (!negative) {
            if (magnitude > max) return std::nullopt;
            return static_cast<std::int64_t>(magnitude);
        }
        if (magnitude > max + 1u) return std::nullopt;
        if (magnitude == max + 1u) return std::numeric_limits<std::int64_t>::min();
        return -static_cast<std::int64_t>(magnitude);
    }
    [[nodiscard]] std::optional<std::uint64_t> as_uint64() const {
        if (negative && magnitude != 0) return std::nullopt;
        return magnitude;
    }
    // Two's-complement bit pattern truncated to 64 bits (what goes on the wire).
    [[nodiscard]] std::uint64_t bits() const { return negative ? (~magnitude + 1u) : magnitude; }
    [[nodiscard]] bool fits_signed_bits(unsigned bits) const;
    [[nodiscard]] bool fits_unsigned_bits(unsigned bits) const;

    friend constexpr bool operator==(const Number& a, const Number& b) {
        return a.magnitude == b.magnitude && (a.negative == b.negative || a.magnitude == 0);
    }
};

enum class NumberSyntax { decimal, hash_hex, c_hex };

enum class NumberError { none, empty, bad_digit, no_digits, overflow };

struct ParsedNumber {
    Number value;
    NumberSyntax syntax = NumberSyntax::decimal;
    NumberError error = NumberError::none;
    [[nodiscard]] bool ok() const { return error == NumberError::none; }
};

// Parses after trimming surrounding whitespace. Accepts [+-]decimal, [+-]#xHEX and [+-]0xHEX.
[[nodiscard]] ParsedNumber parse_number(std::string_view text);

[[nodiscard]] std::string_view to_string(NumberError error);

// ESI spelling of a value: "#x" with at least `min_digits` upper-case hex digits.
[[nodiscard]] std::string format_hex(std::uint64_t value, int min_digits = 0);
[[nodiscard]] std::string format_decimal(const Number& value);

// xs:boolean: true/false/1/0 after trimming whitespace.
[[nodiscard]] std::optional<bool> parse_boolean(std::string_view text);

// Without surrounding XML white space (space, tab, CR, LF). Defined here so that it inlines:
// reading and linting the corpus trims about a million values and names.
[[nodiscard]] inline std::string_view trim(std::string_view text) {
    const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
    return text;
}

}  // namespace esi
