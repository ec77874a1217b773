// The value and the access of an object entry or DataType SubItem as a master sees them over SDO:
// defaults and limits as the bytes read (little-endian, as CoE transfers them, ETG.1000.6), and
// Access/ReadRestrictions/WriteRestrictions as what may be read and written in which state.

#include <algorithm>
#include <cctype>
#include <set>

#include "diff/compare_dictionary.hpp"

namespace esi::diff_detail {

namespace {

// ---- values --------------------------------------------------------------------------------
std::size_t value_bytes(std::uint64_t bit_size) {
    if (bit_size == 0 || bit_size > 64) return 8;
    return static_cast<std::size_t>((bit_size + 7) / 8);
}

std::vector<std::uint8_t> little_endian(std::uint64_t bits, std::size_t n) {
    std::vector<std::uint8_t> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>(i < 8 ? (bits >> (8 * i)) & 0xFF : 0);
    return out;
}

std::string spell_number(const Number& n, bool as_hex) {
    if (as_hex && !n.negative) return hex(n.magnitude, 2);
    return format_decimal(n);
}

// Interprets up to 8 little-endian bytes as a number (sign-extended for signed types).
std::optional<Number> number_of(const std::vector<std::uint8_t>& bytes, bool is_signed) {
    if (bytes.empty() || bytes.size() > 8) return std::nullopt;
    std::uint64_t v = 0;
    for (std::size_t i = bytes.size(); i-- > 0;) v = (v << 8) | bytes[i];
    if (is_signed && (bytes.back() & 0x80) && bytes.size() < 8) v |= ~std::uint64_t{0} << (8 * bytes.size());
    if (is_signed && (v >> 63)) return Number::from_signed(static_cast<std::int64_t>(v));
    return Number::from_unsigned(v);
}

}  // namespace

EntryValue value_of(const std::optional<Number>& number, const std::optional<HexData>& data,
                    const std::optional<std::string>& string, std::uint64_t bit_size, const BasicType* basic, bool as_hex) {
    EntryValue v;
    const bool is_signed = basic && basic->is_signed();
    if (number) {
        v.present = true;
        v.bytes = little_endian(number->bits(), value_bytes(bit_size));
        v.display = spell_number(*number, as_hex);
        v.number = *number;
    } else if (data) {
        v.present = true;
        v.bytes = data->bytes();
        v.raw = normalized_hex(*data);
        v.display = v.raw.empty() ? std::string("(empty data)") : "data " + v.raw;
        if (v.bytes) v.number = number_of(*v.bytes, is_signed);
    } else if (string) {
        v.present = true;
        v.bytes = std::vector<std::uint8_t>(string->begin(), string->end());
        v.display = quote(*string);
    }
    return v;
}

bool same_value(const EntryValue& a, const EntryValue& b) {
    if (a.present != b.present) return false;
    if (!a.present) return true;
    if (a.bytes && b.bytes) return *a.bytes == *b.bytes;
    return a.raw == b.raw && a.display == b.display;
}

namespace {

// ---- access --------------------------------------------------------------------------------

// What a master may do with an entry: read and write, each in PreOP, SafeOP, OP (bits 0..2).
struct Permissions {
    unsigned read = 0;
    unsigned write = 0;
    bool understood = true;
};

std::string lower(std::string_view s) {
    std::string out(trim(s));
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// ETG.2000 AccessType @ReadRestrictions/@WriteRestrictions: PreOP, SafeOP, OP joined by '_'.
unsigned states_of(const std::optional<std::string>& restriction, bool& understood) {
    if (!restriction || trim(*restriction).empty()) return 7;
    unsigned states = 0;
    const std::string s = lower(*restriction);
    std::size_t start = 0;
    while (start <= s.size()) {
        const std::size_t end = std::min(s.find('_', start), s.size());
        const std::string token = s.substr(start, end - start);
        if (token == "preop")
            states |= 1;
        else if (token == "safeop")
            states |= 2;
        else if (token == "op")
            states |= 4;
        else
            understood = false;
        start = end + 1;
    }
    return states;
}

Permissions permissions_of(const ObjectFlags* flags) {
    Permissions p;
    // An entry without Access is read-only, as masters (and ET9300-generated code) treat it.
    const std::string access = flags && flags->access ? lower(*flags->access) : std::string("ro");
    const bool readable = access == "ro" || access == "rw";
    const bool writable = access == "rw" || access == "wo";
    if (!readable && !writable) p.understood = false;
    if (readable) p.read = states_of(flags ? flags->access_read_restrictions : std::nullopt, p.understood);
    if (writable) p.write = states_of(flags ? flags->access_write_restrictions : std::nullopt, p.understood);
    return p;
}

std::set<char> mapping_letters(const std::optional<std::string>& mapping) {
    std::set<char> out;
    if (!mapping) return out;
    for (char c : *mapping)
        if (!std::isspace(static_cast<unsigned char>(c)))
            out.insert(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    return out;
}

void compare_mapping(Recorder& r, const std::string& path, std::string_view what, const std::optional<std::string>& a,
                     const std::optional<std::string>& b, SourcePos pa, SourcePos pb) {
    const std::set<char> la = mapping_letters(a);
    const std::set<char> lb = mapping_letters(b);
    if (la == lb) return;  // "RT" and "TR" are the same set
    const bool lost = !std::includes(lb.begin(), lb.end(), la.begin(), la.end());
    r.value(lost ? ChangeKind::object_pdo_mapping_removed : ChangeKind::object_pdo_mapping_added, path, what, text(a), text(b),
            pa, pb);
}

bool same_flags(const ObjectFlags* a, const ObjectFlags* b) {
    if (!a || !b) return a == b;
    return a->access == b->access && a->access_read_restrictions == b->access_read_restrictions &&
           a->access_write_restrictions == b->access_write_restrictions && a->category == b->category &&
           a->pdo_mapping == b->pdo_mapping && a->safety_mapping == b->safety_mapping && a->attribute == b->attribute &&
           a->transition == b->transition && a->sdo_access == b->sdo_access && a->backup == b->backup &&
           a->setting == b->setting && a->extras.empty() && b->extras.empty();
}

}  // namespace

void compare_flags(Recorder& r, const std::string& p, const ObjectFlags* a, const ObjectFlags* b, SourcePos pa, SourcePos pb) {
    if (same_flags(a, b)) return;
    if (a && a->pos.known()) pa = a->pos;
    if (b && b->pos.known()) pb = b->pos;
    const Permissions xa = permissions_of(a);
    const Permissions xb = permissions_of(b);
    auto access_text = [](const ObjectFlags* f) {
        std::string s = f && f->access ? std::string(trim(*f->access)) : std::string("ro");
        if (f && f->access_read_restrictions) s += " ReadRestrictions=" + *f->access_read_restrictions;
        if (f && f->access_write_restrictions) s += " WriteRestrictions=" + *f->access_write_restrictions;
        return s;
    };
    const std::string ta = access_text(a);
    const std::string tb = access_text(b);
    if (ta != tb) {
        ChangeKind kind = ChangeKind::object_access_narrowed;
        if (xa.understood && xb.understood) {
            const bool lost = (xa.read & ~xb.read) != 0 || (xa.write & ~xb.write) != 0;
            const bool gained = (xb.read & ~xa.read) != 0 || (xb.write & ~xa.write) != 0;
            kind = lost     ? ChangeKind::object_access_narrowed
                   : gained ? ChangeKind::object_access_widened
                            : ChangeKind::spelling_changed;
        }
        r.value(kind, child(p, "Access"), "Access", ta, tb, pa, pb);
    }
    compare_mapping(r, child(p, "PdoMapping"), "PdoMapping", a ? a->pdo_mapping : std::nullopt, b ? b->pdo_mapping : std::nullopt,
                    pa, pb);
    compare_mapping(r, child(p, "SafetyMapping"), "SafetyMapping", a ? a->safety_mapping : std::nullopt,
                    b ? b->safety_mapping : std::nullopt, pa, pb);
    const auto other = [&](std::string_view name, std::optional<std::string> x, std::optional<std::string> y) {
        r.value(ChangeKind::object_flags_changed, child(p, name), name, x, y, pa, pb);
    };
    other("Category", a ? text(a->category) : std::nullopt, b ? text(b->category) : std::nullopt);
    other("Attribute", a ? hex(a->attribute, 2) : std::nullopt, b ? hex(b->attribute, 2) : std::nullopt);
    other("Transition", a ? text(a->transition) : std::nullopt, b ? text(b->transition) : std::nullopt);
    other("SdoAccess", a ? text(a->sdo_access) : std::nullopt, b ? text(b->sdo_access) : std::nullopt);
    other("Backup", a ? dec(a->backup) : std::nullopt, b ? dec(b->backup) : std::nullopt);
    other("Setting", a ? dec(a->setting) : std::nullopt, b ? dec(b->setting) : std::nullopt);
    static const Extras none;
    compare_extras(r, child(p, "Flags"), a ? a->extras : none, b ? b->extras : none, pa, pb);
}

}  // namespace esi::diff_detail
