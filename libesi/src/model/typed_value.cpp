#include "esi/model/typed_value.hpp"

#include <bit>
#include <cstring>

namespace esi {

namespace {

bool is_integer_like(const BasicType& t) { return t.is_integer(); }

std::string describe(const ValueType& type) {
    if (!type.name.empty()) return type.name;
    return type.basic ? std::string(type.basic->esi_name) : std::string("its type");
}

unsigned value_bits(const ValueType& type) {
    if (type.bit_size > 0 && type.bit_size <= 64) return static_cast<unsigned>(type.bit_size);
    if (type.basic && type.basic->bit_size > 0 && type.basic->bit_size <= 64) return type.basic->bit_size;
    return 0;
}

}  // namespace

std::optional<Number> integer_value(const SourceValue& value, const ValueType& type, std::string& error) {
    if (!type.basic || !is_integer_like(*type.basic)) {
        error = "'" + describe(type) + "' is not an integer type";
        return std::nullopt;
    }
    Number n;
    switch (value.kind) {
        case SourceValue::Kind::integer: n = value.integer; break;
        case SourceValue::Kind::boolean: n = Number::from_unsigned(value.boolean ? 1 : 0); break;
        case SourceValue::Kind::text: {
            if (type.enumeration) {
                for (const auto& e : type.enumeration->enums)
                    for (const auto& t : e.texts)
                        if (t.text == value.text) return e.value;
            }
            error = "'" + value.text + "' is not a number" +
                    (type.enumeration ? " or a value of the enumeration " + type.enumeration->name : std::string());
            return std::nullopt;
        }
        case SourceValue::Kind::real:
            error = value.text + " is not an integer; " + describe(type) + " holds whole numbers";
            return std::nullopt;
    }
    const unsigned bits = value_bits(type);
    if (bits == 0) {
        error = "'" + describe(type) + "' has no fixed size";
        return std::nullopt;
    }
    const bool fits = type.basic->is_signed() ? n.fits_signed_bits(bits) : n.fits_unsigned_bits(bits);
    if (!fits) {
        std::string range;
        if (type.basic->is_signed()) {
            const std::uint64_t half = std::uint64_t{1} << (bits - 1);
            range = "-" + std::to_string(half) + ".." + std::to_string(half - 1);
        } else {
            range = "0.." + (bits >= 64 ? std::string("18446744073709551615") : std::to_string((std::uint64_t{1} << bits) - 1));
        }
        error = format_decimal(n) + " does not fit " + describe(type) + " (" + std::to_string(bits) + " bit" +
                (bits == 1 ? "" : "s") + ", " + range + ")";
        return std::nullopt;
    }
    return n;
}

EncodedValue encode_value(const SourceValue& value, const ValueType& type) {
    EncodedValue out;
    if (!type.basic) {
        out.error = "the type '" + describe(type) + "' is not a basic type; give the bytes with 'data'";
        return out;
    }
    const BasicType& basic = *type.basic;
    if (is_integer_like(basic)) {
        const std::optional<Number> n = integer_value(value, type, out.error);
        if (!n) return out;
        const unsigned bits = value_bits(type);
        const std::uint64_t pattern = n->bits();
        for (unsigned i = 0; i < (bits + 7) / 8; ++i) out.bytes.push_back(static_cast<std::uint8_t>(pattern >> (8 * i)));
        return out;
    }
    if (basic.type_class == TypeClass::real) {
        if (value.kind != SourceValue::Kind::integer && value.kind != SourceValue::Kind::real) {
            out.error = "'" + value.text + "' is not a number for " + describe(type);
            return out;
        }
        std::uint64_t pattern = 0;
        unsigned bytes = 0;
        if (basic.bit_size == 32) {
            const auto f = static_cast<float>(value.real);
            pattern = std::bit_cast<std::uint32_t>(f);
            bytes = 4;
        } else {
            pattern = std::bit_cast<std::uint64_t>(value.real);
            bytes = 8;
        }
        for (unsigned i = 0; i < bytes; ++i) out.bytes.push_back(static_cast<std::uint8_t>(pattern >> (8 * i)));
        return out;
    }
    if (basic.type_class == TypeClass::visible_string) {
        const std::uint64_t capacity = type.bit_size / 8;
        if (capacity > 0 && value.text.size() > capacity) {
            out.error = "'" + value.text + "' has " + std::to_string(value.text.size()) + " characters; " + describe(type) +
                        " holds " + std::to_string(capacity);
            return out;
        }
        out.bytes.assign(value.text.begin(), value.text.end());
        return out;
    }
    out.error = "a value of type '" + describe(type) + "' cannot be written as a number or text; give the bytes with 'data'";
    return out;
}

}  // namespace esi
