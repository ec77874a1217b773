#include "check/od_text.hpp"

#include "esi/number.hpp"

namespace esi::rules {

std::string object_address(std::uint32_t index) { return format_hex(index, 4); }

std::string entry_address(std::uint32_t index, std::uint32_t subindex) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string out = format_hex(index, 4);
    out.push_back(':');
    if (subindex > 0xFF) return out + format_hex(subindex).substr(2);
    out.push_back(digits[(subindex >> 4) & 0xF]);
    out.push_back(digits[subindex & 0xF]);
    return out;
}

std::string bits_text(std::uint64_t bits) { return std::to_string(bits) + (bits == 1 ? " bit" : " bits"); }

std::string entry_label(const PdoEntry& entry) {
    if (entry.index_invalid) return "Entry '" + primary_text(entry.names) + "'";
    return "Entry " + entry_address(entry.index, entry.effective_subindex());
}

ValueKind value_kind(const BasicType& type) {
    switch (type.type_class) {
        case TypeClass::signed_integer: return ValueKind::signed_integer;
        case TypeClass::unsigned_integer:
        case TypeClass::boolean:
        case TypeClass::bit:
        case TypeClass::bit_string: return ValueKind::unsigned_integer;
        case TypeClass::real: return ValueKind::real;
        case TypeClass::visible_string:
        case TypeClass::octet_string:
        case TypeClass::unicode_string: return ValueKind::text;
        default: return ValueKind::other;
    }
}

std::string_view to_string(ValueKind kind) {
    switch (kind) {
        case ValueKind::signed_integer: return "signed";
        case ValueKind::unsigned_integer: return "unsigned";
        case ValueKind::real: return "floating point";
        case ValueKind::text: return "string";
        case ValueKind::other: return "other";
    }
    return "other";
}

}  // namespace esi::rules
