#include "codegen/values.hpp"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <string_view>

#include "esi/codegen/identifier.hpp"

namespace esi::codegen {

namespace {

std::uint64_t mask_for(std::uint64_t bit_length) {
    if (bit_length == 0 || bit_length >= 64) return ~std::uint64_t{0};
    return (std::uint64_t{1} << bit_length) - 1u;
}

std::int64_t sign_extend(std::uint64_t bits, std::uint64_t bit_length) {
    if (bit_length == 0 || bit_length >= 64) return static_cast<std::int64_t>(bits);
    const std::uint64_t sign = std::uint64_t{1} << (bit_length - 1);
    bits &= mask_for(bit_length);
    return static_cast<std::int64_t>((bits ^ sign) - sign);
}

std::uint64_t little_endian(const std::vector<std::uint8_t>& bytes) {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < bytes.size() && k < 8; ++k) v |= std::uint64_t{bytes[k]} << (8 * k);
    return v;
}

// The three possible spellings of one value, whichever the file gave.
struct RawValue {
    const Number* number = nullptr;
    const HexData* data = nullptr;
    const std::string* string = nullptr;
    [[nodiscard]] bool empty() const { return !number && !data && !string; }
};

DecodedValue decode_integer(const RawValue& raw, bool is_signed, std::uint64_t bit_length) {
    DecodedValue out;
    std::uint64_t bits = 0;
    std::optional<std::int64_t> exact;
    if (raw.number) {
        bits = raw.number->bits();
        exact = raw.number->as_int64();
    } else if (raw.data) {
        const auto bytes = raw.data->bytes();
        if (!bytes) return out;
        bits = little_endian(*bytes);
        const std::uint64_t width = bit_length ? bit_length : 8 * std::min<std::size_t>(bytes->size(), 8);
        if (is_signed) exact = sign_extend(bits, width);
    } else if (raw.string) {
        const ParsedNumber parsed = parse_number(*raw.string);
        if (!parsed.ok()) return out;
        bits = parsed.value.bits();
        exact = parsed.value.as_int64();
    } else {
        return out;
    }
    out.bits = bits & mask_for(bit_length);
    if (is_signed) {
        out.kind = DecodedValue::Kind::signed_integer;
        // A value that does not fit the type is shown as the bits that go on the wire.
        out.i = exact && sign_extend(out.bits, bit_length) == *exact ? *exact : sign_extend(out.bits, bit_length);
    } else {
        out.kind = DecodedValue::Kind::unsigned_integer;
        out.i = static_cast<std::int64_t>(out.bits);
    }
    return out;
}

DecodedValue decode_real(const RawValue& raw, std::uint64_t bit_length) {
    DecodedValue out;
    const bool single = bit_length != 64;
    if (raw.data) {
        // DefaultData holds the IEEE 754 bytes as they go over SDO.
        const auto bytes = raw.data->bytes();
        if (!bytes) return out;
        const std::uint64_t bits = little_endian(*bytes);
        out.r = single ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits))) : std::bit_cast<double>(bits);
    } else if (raw.number) {
        // DefaultValue of a REAL is the number itself (HexDecValue has no fraction).
        const auto v = raw.number->as_int64();
        out.r = v ? static_cast<double>(*v) : static_cast<double>(raw.number->magnitude);
        if (raw.number->negative && !v) out.r = -out.r;
    } else if (raw.string) {
        const std::string& s = *raw.string;
        double v = 0.0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec != std::errc{} || end != s.data() + s.size()) return out;
        out.r = v;
    } else {
        return out;
    }
    out.kind = DecodedValue::Kind::real;
    out.bits = single ? std::bit_cast<std::uint32_t>(static_cast<float>(out.r)) : std::bit_cast<std::uint64_t>(out.r);
    return out;
}

DecodedValue decode_text(const RawValue& raw, DecodedValue::Kind kind) {
    DecodedValue out;
    if (raw.string) {
        out.text = *raw.string;
    } else if (raw.data) {
        const auto bytes = raw.data->bytes();
        if (!bytes) return out;
        out.text.assign(bytes->begin(), bytes->end());
    } else {
        return out;
    }
    out.kind = kind;
    return out;
}

DecodedValue decode(const RawValue& raw, ValueClass cls, std::uint64_t bit_length) {
    if (raw.empty()) return {};
    switch (cls) {
        case ValueClass::signed_integer: return decode_integer(raw, true, bit_length);
        case ValueClass::unsigned_integer: return decode_integer(raw, false, bit_length);
        case ValueClass::real: return decode_real(raw, bit_length);
        case ValueClass::string: return decode_text(raw, DecodedValue::Kind::string);
        case ValueClass::bytes: return decode_text(raw, DecodedValue::Kind::bytes);
    }
    return {};
}

std::string format_real(double r, bool single) {
    if (std::isnan(r)) return "__builtin_nan(\"\")";
    if (std::isinf(r)) return r < 0 ? "(-__builtin_inf())" : "__builtin_inf()";
    char buffer[64];
    // 9 (float) / 17 (double) significant digits read back to the same value.
    std::snprintf(buffer, sizeof buffer, single ? "%.9g" : "%.17g", r);
    std::string s = buffer;
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    return s;
}

ShortText signed_literal(std::int64_t v) {
    ShortText out;
    if (v == INT64_MIN) {
        constexpr std::string_view min = "(-9223372036854775807LL - 1)";
        min.copy(out.data, min.size());
        out.size = static_cast<std::uint8_t>(min.size());
        return out;
    }
    const auto r = std::to_chars(out.data, out.data + sizeof out.data, v);
    char* end = r.ptr;
    if (v < INT32_MIN || v > INT32_MAX) {
        *end++ = 'L';
        *end++ = 'L';
    }
    out.size = static_cast<std::uint8_t>(end - out.data);
    return out;
}

ShortText unsigned_literal(std::uint64_t v, std::uint64_t bit_length) {
    const int digits = static_cast<int>(std::min<std::uint64_t>((bit_length + 3) / 4, 16));
    ShortText out = hex_text(v, digits);
    for (const char c : std::string_view(v > 0xFFFFFFFFu ? "ull" : "u")) out.data[out.size++] = c;
    return out;
}

std::string bytes_text(const std::string& bytes) {
    std::string out;
    char buffer[4];
    for (const char c : bytes) {
        if (!out.empty()) out += ' ';
        std::snprintf(buffer, sizeof buffer, "%02X", static_cast<unsigned char>(c));
        out += buffer;
    }
    return out;
}

}  // namespace

ShortText plain_hex_text(std::uint64_t value, int digits) {
    static constexpr char digit_chars[] = "0123456789ABCDEF";
    int needed = 1;
    while (needed < 16 && (value >> (4 * needed)) != 0) ++needed;
    const int width = std::clamp(std::max(digits, needed), 1, 28);
    ShortText out;
    for (int k = 0; k < width; ++k) {
        const int shift = 4 * (width - 1 - k);
        out.data[k] = shift >= 64 ? '0' : digit_chars[(value >> shift) & 0xFu];
    }
    out.size = static_cast<std::uint8_t>(width);
    return out;
}

ShortText hex_text(std::uint64_t value, int digits) {
    const ShortText plain = plain_hex_text(value, digits);
    ShortText out;
    out.data[0] = '0';
    out.data[1] = 'x';
    std::memcpy(out.data + 2, plain.data, plain.size);
    out.size = static_cast<std::uint8_t>(plain.size + 2);
    return out;
}

ValueClass value_class_of(const BasicType* basic) {
    if (!basic) return ValueClass::bytes;
    switch (basic->type_class) {
        case TypeClass::signed_integer: return ValueClass::signed_integer;
        case TypeClass::boolean:
        case TypeClass::bit:
        case TypeClass::unsigned_integer:
        case TypeClass::bit_string: return ValueClass::unsigned_integer;
        case TypeClass::real: return ValueClass::real;
        case TypeClass::visible_string: return ValueClass::string;
        default: return ValueClass::bytes;
    }
}

EntryValues decode_entry_values(const ObjectEntry& entry) {
    RawValue def, min, max;
    if (entry.info) {
        const ObjectInfo& info = *entry.info;
        if (info.default_value) def.number = &*info.default_value;
        else if (info.default_data) def.data = &*info.default_data;
        else if (info.default_string) def.string = &*info.default_string;
        if (info.min_value) min.number = &*info.min_value;
        else if (info.min_data) min.data = &*info.min_data;
        if (info.max_value) max.number = &*info.max_value;
        else if (info.max_data) max.data = &*info.max_data;
    }
    if (entry.type_item) {
        const DataTypeSubItem& item = *entry.type_item;
        if (def.empty()) {
            if (item.default_value) def.number = &*item.default_value;
            else if (item.default_data) def.data = &*item.default_data;
            else if (item.default_string) def.string = &*item.default_string;
        }
        if (min.empty() && item.min_value) min.number = &*item.min_value;
        if (max.empty() && item.max_value) max.number = &*item.max_value;
    }
    const ValueClass cls = value_class_of(entry.basic);
    return {decode(def, cls, entry.bit_size), decode(min, cls, entry.bit_size), decode(max, cls, entry.bit_size)};
}

bool has_bits(const DecodedValue& value) {
    using Kind = DecodedValue::Kind;
    return value.kind == Kind::signed_integer || value.kind == Kind::unsigned_integer || value.kind == Kind::real;
}

bool fits_32_bits(const DecodedValue& value) { return has_bits(value) && value.bits <= 0xFFFFFFFFu; }

namespace {
int bits_hex_digits(std::uint64_t bit_length) {
    return static_cast<int>(std::min<std::uint64_t>(std::max<std::uint64_t>((bit_length + 3) / 4, 1), 16));
}
}  // namespace

ShortText bits32_hex(const DecodedValue& value, std::uint64_t bit_length) {
    return hex_text(has_bits(value) ? (value.bits & 0xFFFFFFFFu) : 0, std::min(bits_hex_digits(bit_length), 8));
}

ViewValue value_view(ViewArena& arena, const DecodedValue& value, std::uint64_t bit_length) {
    using Kind = DecodedValue::Kind;
    ObjectBuilder v(arena);
    v.add("present", value.kind != Kind::none);
    ViewValue kind = ViewValue::of_static("none"), kind_upper = ViewValue::of_static("NONE"), text = ViewValue::of_static("");
    ViewValue int_literal = ViewValue::of_static("0"), uint_literal = ViewValue::of_static("0u"), real_literal = ViewValue::of_static("0.0");
    ViewValue string_literal = ViewValue::of_static("\"\"");
    std::uint64_t byte_count = 0;
    char number[32];
    switch (value.kind) {
        case Kind::none: break;
        case Kind::signed_integer: {
            kind = ViewValue::of_static("signed_integer");
            kind_upper = ViewValue::of_static("SIGNED_INTEGER");
            const auto r = std::to_chars(number, number + sizeof number, value.i);
            text = arena.string(std::string_view(number, static_cast<std::size_t>(r.ptr - number)));
            int_literal = arena.string(signed_literal(value.i));
            uint_literal = arena.string(unsigned_literal(value.bits, bit_length));
            break;
        }
        case Kind::unsigned_integer: {
            kind = ViewValue::of_static("unsigned_integer");
            kind_upper = ViewValue::of_static("UNSIGNED_INTEGER");
            const auto r = std::to_chars(number, number + sizeof number, value.bits);
            text = arena.string(std::string_view(number, static_cast<std::size_t>(r.ptr - number)));
            uint_literal = arena.string(unsigned_literal(value.bits, bit_length));
            break;
        }
        case Kind::real: {
            kind = ViewValue::of_static("real");
            kind_upper = ViewValue::of_static("REAL");
            const std::string literal = format_real(value.r, bit_length != 64);
            real_literal = arena.string(literal);
            text = literal.find("__builtin") != std::string::npos
                       ? ViewValue::of_static(std::isnan(value.r) ? "nan" : (value.r < 0 ? "-inf" : "inf"))
                       : real_literal;
            uint_literal = arena.string(unsigned_literal(value.bits, bit_length ? bit_length : 32));
            break;
        }
        case Kind::string:
            kind = ViewValue::of_static("string");
            kind_upper = ViewValue::of_static("STRING");
            text = arena.string(value.text);
            string_literal = arena.string(c_string_literal(value.text));
            byte_count = value.text.size();
            break;
        case Kind::bytes:
            kind = ViewValue::of_static("bytes");
            kind_upper = ViewValue::of_static("BYTES");
            text = arena.string(bytes_text(value.text));
            string_literal = arena.string(c_string_literal(value.text));
            byte_count = value.text.size();
            break;
    }
    v.add("kind", kind);
    v.add("kind_upper", kind_upper);
    v.add("is_text", value.kind == Kind::string || value.kind == Kind::bytes);
    v.add("text", text);
    v.add("int_literal", int_literal);
    v.add("uint_literal", uint_literal);
    v.add("real_literal", real_literal);
    v.add("string_literal", string_literal);
    v.add("byte_count", byte_count);
    const int digits = bits_hex_digits(bit_length);
    v.add("bits_hex", has_bits(value) ? arena.string(hex_text(value.bits, digits)) : ViewValue::of_static(""));
    v.add("fits_32_bits", fits_32_bits(value));
    v.add("bits32_hex", bits32_hex(value, bit_length));
    return v.finish();
}

}  // namespace esi::codegen
