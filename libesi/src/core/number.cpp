#include "esi/number.hpp"

#include <array>
#include <limits>

namespace esi {

bool Number::fits_signed_bits(unsigned bits) const {
    if (bits == 0) return false;
    if (bits >= 64) return as_int64().has_value();
    const std::uint64_t limit = std::uint64_t{1} << (bits - 1);
    return negative ? magnitude <= limit : magnitude < limit;
}

bool Number::fits_unsigned_bits(unsigned bits) const {
    if (negative && magnitude != 0) return false;
    if (bits >= 64) return true;
    return magnitude < (std::uint64_t{1} << bits);
}

ParsedNumber parse_number(std::string_view text) {
    ParsedNumber result;
    text = trim(text);
    if (text.empty()) {
        result.error = NumberError::empty;
        return result;
    }
    bool negative = false;
    if (text.front() == '+' || text.front() == '-') {
        negative = text.front() == '-';
        text.remove_prefix(1);
    }
    unsigned base = 10;
    if (text.size() >= 2 && text[0] == '#' && (text[1] == 'x' || text[1] == 'X')) {
        base = 16;
        result.syntax = NumberSyntax::hash_hex;
        text.remove_prefix(2);
    } else if (text.size() >= 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        base = 16;
        result.syntax = NumberSyntax::c_hex;
        text.remove_prefix(2);
    }
    if (text.empty()) {
        result.error = NumberError::no_digits;
        return result;
    }
    // value * base + digit overflows when value exceeds max / base, or equals it and the digit
    // exceeds max % base. The limits are constants per base: a 64-bit division per digit cost
    // more time than the rest of the loop.
    constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    const std::uint64_t limit = base == 16 ? max / 16 : max / 10;
    const unsigned last_digit = base == 16 ? static_cast<unsigned>(max % 16) : static_cast<unsigned>(max % 10);
    // Up to 15 hex or 19 decimal digits cannot overflow: nearly every number of a file is read
    // without the test per digit.
    const bool may_overflow = text.size() > (base == 16 ? 15u : 19u);
    std::uint64_t value = 0;
    for (char c : text) {
        const unsigned digit = hex_digit_values[static_cast<unsigned char>(c)];
        if (digit >= base) {
            result.error = NumberError::bad_digit;
            return result;
        }
        if (may_overflow && (value > limit || (value == limit && digit > last_digit))) {
            result.error = NumberError::overflow;
            return result;
        }
        value = value * base + digit;
    }
    result.value = Number{value, negative && value != 0};
    return result;
}

std::string_view to_string(NumberError error) {
    switch (error) {
        case NumberError::none: return "no error";
        case NumberError::empty: return "empty value";
        case NumberError::bad_digit: return "not a number";
        case NumberError::no_digits: return "hex prefix without digits";
        case NumberError::overflow: return "value does not fit in 64 bits";
    }
    return "not a number";
}

std::string format_hex(std::uint64_t value, int min_digits) {
    static constexpr char digits[] = "0123456789ABCDEF";
    char buffer[16];
    int n = 0;
    do {
        buffer[n++] = digits[value & 0xF];
        value >>= 4;
    } while (value != 0);
    std::string out = "#x";
    for (int i = n; i < min_digits; ++i) out.push_back('0');
    while (n > 0) out.push_back(buffer[--n]);
    return out;
}

std::string format_decimal(const Number& value) {
    std::string digits = std::to_string(value.magnitude);
    return value.negative && value.magnitude != 0 ? "-" + digits : digits;
}

std::optional<bool> parse_boolean(std::string_view text) {
    text = trim(text);
    if (text == "true" || text == "1") return true;
    if (text == "false" || text == "0") return false;
    return std::nullopt;
}

}  // namespace esi
