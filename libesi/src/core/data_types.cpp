#include "esi/data_types.hpp"

#include <algorithm>
#include <array>
#include <charconv>

#include "esi/number.hpp"

namespace esi {

namespace {

using TC = TypeClass;

// ETG.1000.6 / CiA 301 data type codes with their ESI names (ET9300 Table 22).
constexpr BasicType table[] = {
    {"BOOL", "BOOLEAN", 0x0001, 1, TC::boolean},
    {"SINT", "INTEGER8", 0x0002, 8, TC::signed_integer},
    {"INT", "INTEGER16", 0x0003, 16, TC::signed_integer},
    {"DINT", "INTEGER32", 0x0004, 32, TC::signed_integer},
    {"USINT", "UNSIGNED8", 0x0005, 8, TC::unsigned_integer},
    {"UINT", "UNSIGNED16", 0x0006, 16, TC::unsigned_integer},
    {"UDINT", "UNSIGNED32", 0x0007, 32, TC::unsigned_integer},
    {"REAL", "REAL32", 0x0008, 32, TC::real},
    {"STRING", "VISIBLE_STRING", 0x0009, 0, TC::visible_string},
    {"OCTET_STRING", "OCTET_STRING", 0x000A, 0, TC::octet_string},
    {"UNICODE_STRING", "UNICODE_STRING", 0x000B, 0, TC::unicode_string},
    {"TIME_OF_DAY", "TIME_OF_DAY", 0x000C, 48, TC::time},
    {"TIME_DIFFERENCE", "TIME_DIFFERENCE", 0x000D, 48, TC::time},
    {"DOMAIN", "DOMAIN", 0x000F, 0, TC::domain},
    {"INT24", "INTEGER24", 0x0010, 24, TC::signed_integer},
    {"LREAL", "REAL64", 0x0011, 64, TC::real},
    {"INT40", "INTEGER40", 0x0012, 40, TC::signed_integer},
    {"INT48", "INTEGER48", 0x0013, 48, TC::signed_integer},
    {"INT56", "INTEGER56", 0x0014, 56, TC::signed_integer},
    {"LINT", "INTEGER64", 0x0015, 64, TC::signed_integer},
    {"UINT24", "UNSIGNED24", 0x0016, 24, TC::unsigned_integer},
    {"UINT40", "UNSIGNED40", 0x0018, 40, TC::unsigned_integer},
    {"UINT48", "UNSIGNED48", 0x0019, 48, TC::unsigned_integer},
    {"UINT56", "UNSIGNED56", 0x001A, 56, TC::unsigned_integer},
    {"ULINT", "UNSIGNED64", 0x001B, 64, TC::unsigned_integer},
    {"GUID", "GUID", 0x001D, 128, TC::guid},
    {"BYTE", "BYTE", 0x001E, 8, TC::bit_string},
    {"WORD", "WORD", 0x001F, 16, TC::bit_string},
    {"DWORD", "DWORD", 0x0020, 32, TC::bit_string},
    {"PDO_MAPPING", "PDO_MAPPING", 0x0021, 0, TC::structured},
    {"IDENTITY", "IDENTITY", 0x0023, 0, TC::structured},
    {"COMMAND_PAR", "COMMAND_PAR", 0x0025, 0, TC::structured},
    {"PDO_PARAMETER", "PDO_PARAMETER", 0x0027, 0, TC::structured},
    {"ENUM", "ENUM", 0x0028, 0, TC::structured},
    {"SM_SYNCHRONISATION", "SM_SYNCHRONISATION", 0x0029, 0, TC::structured},
    {"RECORD", "RECORD", 0x002A, 0, TC::structured},
    {"BACKUP_PARAMETER", "BACKUP_PARAMETER", 0x002B, 0, TC::structured},
    {"MODULAR_DEVICE_PROFILE", "MODULAR_DEVICE_PROFILE", 0x002C, 0, TC::structured},
    {"BITARR8", "BITARR8", 0x002D, 8, TC::bit_string},
    {"BITARR16", "BITARR16", 0x002E, 16, TC::bit_string},
    {"BITARR32", "BITARR32", 0x002F, 32, TC::bit_string},
    {"BIT1", "BIT1", 0x0030, 1, TC::bit},
    {"BIT2", "BIT2", 0x0031, 2, TC::bit},
    {"BIT3", "BIT3", 0x0032, 3, TC::bit},
    {"BIT4", "BIT4", 0x0033, 4, TC::bit},
    {"BIT5", "BIT5", 0x0034, 5, TC::bit},
    {"BIT6", "BIT6", 0x0035, 6, TC::bit},
    {"BIT7", "BIT7", 0x0036, 7, TC::bit},
    {"BIT8", "BIT8", 0x0037, 8, TC::bit},
    {"BIT9", "BIT9", 0x0038, 9, TC::bit},
    {"BIT10", "BIT10", 0x0039, 10, TC::bit},
    {"BIT11", "BIT11", 0x003A, 11, TC::bit},
    {"BIT12", "BIT12", 0x003B, 12, TC::bit},
    {"BIT13", "BIT13", 0x003C, 13, TC::bit},
    {"BIT14", "BIT14", 0x003D, 14, TC::bit},
    {"BIT15", "BIT15", 0x003E, 15, TC::bit},
    {"BIT16", "BIT16", 0x003F, 16, TC::bit},
};

// Non-standard spellings seen in real files and tools, with the ESI name they mean.
struct Alias {
    std::string_view spelling;
    std::string_view standard;
};
constexpr Alias aliases[] = {
    {"UINT8", "USINT"},   {"UINT16", "UINT"},   {"UINT32", "UDINT"},  {"UINT64", "ULINT"},  {"INT8", "SINT"},
    {"INT16", "INT"},     {"INT32", "DINT"},    {"INT64", "LINT"},    {"BOOLEAN", "BOOL"},  {"BIT", "BOOL"},
    {"FLOAT", "REAL"},    {"DOUBLE", "LREAL"},  {"FLOAT32", "REAL"},  {"FLOAT64", "LREAL"}, {"U8", "USINT"},
    {"U16", "UINT"},      {"U32", "UDINT"},     {"CHAR", "USINT"},    {"UCHAR", "USINT"},
};

std::string_view skip_spaces(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

bool parse_int(std::string_view s, std::int64_t& out) {
    s = trim(s);
    if (s.empty()) return false;
    const auto* first = s.data();
    const auto* last = s.data() + s.size();
    auto [ptr, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && ptr == last;
}

}  // namespace

std::span<const BasicType> basic_types() { return table; }

namespace {

// The basic types by ESI name, for find_basic_type: every type name a lint run resolves is
// first tried as a basic type (over 100,000 times on the corpus, mostly DataType names that are
// not). Names are bucketed by length, first and last letter, which leaves at most three to
// compare (USINT, UDINT, ULINT); a std::unordered_map (hashing the name) cost 160 instructions
// a lookup and a scan of the table more on a miss.
class BasicTypeNames {
public:
    BasicTypeNames() {
        for (const auto& t : table) {
            auto& slot = slots_[key(t.esi_name)];
            const auto free = std::find(slot.begin(), slot.end(), nullptr);
            if (free == slot.end()) overflow_ = true;  // never with today's table; stay correct anyway
            else *free = &t;
        }
    }
    [[nodiscard]] const BasicType* find(std::string_view name) const {
        if (name.empty()) return nullptr;
        if (overflow_) {
            for (const auto& t : table)
                if (t.esi_name == name) return &t;
            return nullptr;
        }
        for (const BasicType* t : slots_[key(name)])
            if (t && t->esi_name == name) return t;
        return nullptr;
    }

private:
    static constexpr std::size_t bucket_count = 256;
    static std::size_t key(std::string_view name) {
        return (name.size() * 67 + static_cast<unsigned char>(name.front()) * 13 + static_cast<unsigned char>(name.back())) %
               bucket_count;
    }
    std::array<std::array<const BasicType*, 3>, bucket_count> slots_{};
    bool overflow_ = false;
};

}  // namespace

const BasicType* find_basic_type(std::string_view esi_name) {
    static const BasicTypeNames names;
    return names.find(esi_name);
}

const BasicType* find_basic_type_by_coe_name(std::string_view coe_name) {
    for (const auto& t : table)
        if (t.coe_name == coe_name) return &t;
    return nullptr;
}

const BasicType* find_basic_type_by_code(std::uint16_t coe_code) {
    for (const auto& t : table)
        if (t.coe_code == coe_code) return &t;
    return nullptr;
}

std::string_view standard_type_name_for(std::string_view nonstandard) {
    for (const auto& a : aliases)
        if (a.spelling == nonstandard) return a.standard;
    if (const BasicType* t = find_basic_type_by_coe_name(nonstandard); t && t->esi_name != nonstandard) return t->esi_name;
    return {};
}

TypeName parse_type_name(std::string_view text) {
    TypeName out;
    const std::string_view s = trim(text);
    out.name = std::string(s);
    if (s.empty()) return out;

    // STRING(n)
    if (s.size() > 7 && s.substr(0, 6) == "STRING" ) {
        std::string_view rest = skip_spaces(s.substr(6));
        if (!rest.empty() && rest.front() == '(' && rest.back() == ')') {
            std::int64_t n = 0;
            if (parse_int(rest.substr(1, rest.size() - 2), n) && n >= 0 && n <= 0xFFFFFFFF) {
                out.kind = TypeName::Kind::string;
                out.string_length = static_cast<std::uint32_t>(n);
                out.basic = find_basic_type("STRING");
                return out;
            }
        }
    }
    // ARRAY [a..b] OF T
    if (s.size() > 5 && s.substr(0, 5) == "ARRAY") {
        std::string_view rest = skip_spaces(s.substr(5));
        const auto open = rest.find('[');
        const auto dots = rest.find("..");
        const auto close = rest.find(']');
        if (open == 0 && dots != std::string_view::npos && close != std::string_view::npos && open < dots && dots < close) {
            std::int64_t lower = 0;
            std::int64_t upper = 0;
            std::string_view tail = skip_spaces(rest.substr(close + 1));
            if (parse_int(rest.substr(open + 1, dots - open - 1), lower) && parse_int(rest.substr(dots + 2, close - dots - 2), upper) &&
                tail.size() > 2 && tail.substr(0, 2) == "OF" && (tail[2] == ' ' || tail[2] == '\t')) {
                out.kind = TypeName::Kind::array;
                out.lower_bound = lower;
                out.upper_bound = upper;
                out.element = std::string(trim(tail.substr(2)));
                out.basic = find_basic_type(out.element);
                return out;
            }
        }
    }
    if (const BasicType* t = find_basic_type(s)) {
        out.kind = TypeName::Kind::basic;
        out.basic = t;
        return out;
    }
    return out;
}

std::optional<std::uint64_t> implied_bit_size(std::string_view type_name) {
    // Only STRING(n) and ARRAY [..] OF names need taking apart; any other name is a basic type or
    // implies nothing (the DataTypes of a Dictionary, DT1018 …), and is not copied into a TypeName.
    if (const std::string_view s = trim(type_name); !s.starts_with("STRING") && !s.starts_with("ARRAY")) {
        const BasicType* basic = find_basic_type(s);
        if (!basic || basic->bit_size == 0) return std::nullopt;
        return basic->bit_size;
    }
    const TypeName t = parse_type_name(type_name);
    switch (t.kind) {
        case TypeName::Kind::basic:
            if (t.basic->bit_size == 0) return std::nullopt;
            return t.basic->bit_size;
        case TypeName::Kind::string: return std::uint64_t{8} * t.string_length;
        case TypeName::Kind::array: {
            std::optional<std::uint64_t> element = implied_bit_size(t.element);
            if (!element) return std::nullopt;
            return *element * t.element_count();
        }
        case TypeName::Kind::named: return std::nullopt;
    }
    return std::nullopt;
}

std::string canonical_type_name(std::string_view type_name) {
    const TypeName t = parse_type_name(type_name);
    switch (t.kind) {
        case TypeName::Kind::basic: return std::string(t.basic->esi_name);
        case TypeName::Kind::string: return "STRING(" + std::to_string(t.string_length) + ")";
        case TypeName::Kind::array:
            return "ARRAY [" + std::to_string(t.lower_bound) + ".." + std::to_string(t.upper_bound) + "] OF " +
                   canonical_type_name(t.element);
        case TypeName::Kind::named: return t.name;
    }
    return t.name;
}

}  // namespace esi
