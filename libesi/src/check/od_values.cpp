#include "check/od_values.hpp"

#include <array>

namespace esi::rules {

namespace {

std::uint64_t width_mask(std::uint64_t bits) { return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1u; }

Number from_pattern(std::uint64_t pattern, const ValueFormat& format) {
    const std::uint64_t bits = format.bit_size == 0 || format.bit_size > 64 ? 64 : format.bit_size;
    pattern &= width_mask(bits);
    if (format.is_signed && bits > 0 && ((pattern >> (bits - 1)) & 1u)) {
        // Negative: magnitude is the two's complement within `bits`.
        return Number{(~pattern + 1u) & width_mask(bits), true};
    }
    return Number::from_unsigned(pattern);
}

}  // namespace

std::optional<std::uint64_t> little_endian_pattern(const HexData& data) {
    const std::string& text = data.text;
    const std::size_t byte_count = text.size() / 2;
    if (text.empty() || text.size() % 2 != 0 || byte_count > 8) return std::nullopt;
    const auto digit = [](char c) -> unsigned { return hex_digit_values[static_cast<unsigned char>(c)]; };
    std::uint64_t pattern = 0;
    for (std::size_t i = 0; i < byte_count; ++i) {
        const unsigned high = digit(text[2 * i]);
        const unsigned low = digit(text[2 * i + 1]);
        if (high > 15 || low > 15) return std::nullopt;  // not hexBinary (HexData::valid)
        pattern |= std::uint64_t(high * 16 + low) << (8 * i);
    }
    return pattern;
}

std::optional<Number> number_from_data(const HexData& data, const ValueFormat& format) {
    const std::optional<std::uint64_t> pattern = little_endian_pattern(data);
    if (!pattern) return std::nullopt;
    ValueFormat effective = format;
    // Data shorter than the entry is zero-extended; the sign bit is the entry's, not the data's.
    if (effective.bit_size == 0 || effective.bit_size > 64) effective.bit_size = 8 * data.byte_length();
    return from_pattern(*pattern, effective);
}

Number normalized(const Number& value, const ValueFormat& format) {
    if (format.bit_size == 0 || format.bit_size > 64 || value.magnitude == 0) return value;
    const std::uint64_t signed_max = width_mask(format.bit_size - 1);
    if (format.is_signed) {
        // #xFFFF for an INT: the bit pattern of -1.
        if (value.negative || value.magnitude <= signed_max || value.magnitude > width_mask(format.bit_size)) return value;
        return from_pattern(value.magnitude, format);
    }
    // -1 for a UDINT: Beckhoff's way of writing 0xFFFFFFFF.
    if (!value.negative || value.magnitude > signed_max + 1) return value;
    return from_pattern(~value.magnitude + 1u, format);
}

template <typename DataField>
std::optional<Number> value_of(const RareOptional<Number>& value, const DataField& data, const ValueFormat& format) {
    if (value) return normalized(*value, format);
    if (data) return number_from_data(*data, format);
    return std::nullopt;
}

std::optional<Number> default_number(const ObjectInfo& info, const ValueFormat& format) {
    return value_of(info.default_value, info.default_data, format);
}
std::optional<Number> min_number(const ObjectInfo& info, const ValueFormat& format) {
    return value_of(info.min_value, info.min_data, format);
}
std::optional<Number> max_number(const ObjectInfo& info, const ValueFormat& format) {
    return value_of(info.max_value, info.max_data, format);
}

Number format_min(const ValueFormat& format) {
    if (!format.is_signed || format.bit_size == 0) return Number{};
    const std::uint64_t bits = format.bit_size > 64 ? 64 : format.bit_size;
    return Number{std::uint64_t{1} << (bits - 1), true};
}

Number format_max(const ValueFormat& format) {
    const std::uint64_t bits = format.bit_size == 0 || format.bit_size > 64 ? 64 : format.bit_size;
    return Number::from_unsigned(format.is_signed ? width_mask(bits - 1) : width_mask(bits));
}

bool less(const Number& a, const Number& b) {
    const bool a_negative = a.negative && a.magnitude != 0;
    const bool b_negative = b.negative && b.magnitude != 0;
    if (a_negative != b_negative) return a_negative;
    if (a_negative) return a.magnitude > b.magnitude;
    return a.magnitude < b.magnitude;
}

}  // namespace esi::rules
