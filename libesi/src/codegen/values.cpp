#include "codegen/values.hpp"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

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

std::string signed_literal(std::int64_t v) {
    if (v == INT64_MIN) return "(-9223372036854775807LL - 1)";
    if (v >= INT32_MIN && v <= INT32_MAX) return std::to_string(v);
    return std::to_string(v) + "LL";
}

std::string unsigned_literal(std::uint64_t v, std::uint64_t bit_length) {
    const int digits = static_cast<int>(std::min<std::uint64_t>((bit_length + 3) / 4, 16));
    return hex(v, digits) + (v > 0xFFFFFFFFu ? "ull" : "u");
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

std::string hex(std::uint64_t value, int digits) {
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "0x%0*llX", digits, static_cast<unsigned long long>(value));
    return buffer;
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

nlohmann::ordered_json value_view(const DecodedValue& value, std::uint64_t bit_length) {
    using Kind = DecodedValue::Kind;
    nlohmann::ordered_json v;
    v["present"] = value.kind != Kind::none;
    std::string kind = "none", text, int_literal = "0", uint_literal = "0u", real_literal = "0.0", string_literal = "\"\"";
    std::uint64_t byte_count = 0;
    bool has_bits = false;
    switch (value.kind) {
        case Kind::none: break;
        case Kind::signed_integer:
            kind = "signed_integer";
            text = std::to_string(value.i);
            int_literal = signed_literal(value.i);
            uint_literal = unsigned_literal(value.bits, bit_length);
            has_bits = true;
            break;
        case Kind::unsigned_integer:
            kind = "unsigned_integer";
            text = std::to_string(value.bits);
            uint_literal = unsigned_literal(value.bits, bit_length);
            has_bits = true;
            break;
        case Kind::real:
            kind = "real";
            text = format_real(value.r, bit_length != 64);
            if (text.find("__builtin") != std::string::npos) text = std::isnan(value.r) ? "nan" : (value.r < 0 ? "-inf" : "inf");
            real_literal = format_real(value.r, bit_length != 64);
            uint_literal = unsigned_literal(value.bits, bit_length ? bit_length : 32);
            has_bits = true;
            break;
        case Kind::string:
            kind = "string";
            text = value.text;
            string_literal = c_string_literal(value.text);
            byte_count = value.text.size();
            break;
        case Kind::bytes:
            kind = "bytes";
            text = bytes_text(value.text);
            string_literal = c_string_literal(value.text);
            byte_count = value.text.size();
            break;
    }
    v["kind"] = kind;
    std::string upper = kind;
    for (auto& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    v["kind_upper"] = upper;
    v["is_text"] = value.kind == Kind::string || value.kind == Kind::bytes;
    v["text"] = text;
    v["int_literal"] = int_literal;
    v["uint_literal"] = uint_literal;
    v["real_literal"] = real_literal;
    v["string_literal"] = string_literal;
    v["byte_count"] = byte_count;
    const int digits = static_cast<int>(std::min<std::uint64_t>(std::max<std::uint64_t>((bit_length + 3) / 4, 1), 16));
    v["bits_hex"] = has_bits ? hex(value.bits, digits) : std::string();
    v["fits_32_bits"] = has_bits && value.bits <= 0xFFFFFFFFu;
    v["bits32_hex"] = hex(has_bits ? (value.bits & 0xFFFFFFFFu) : 0, static_cast<int>(std::min(digits, 8)));
    return v;
}

}  // namespace esi::codegen
