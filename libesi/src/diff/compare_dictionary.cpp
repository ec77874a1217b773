// The object dictionary. Objects pair up by index and DataTypes by (canonical) name: their order
// in the file has no meaning (ETG.2000 Dictionary). Objects are compared the way a master sees
// them over SDO, sub-entry by sub-entry (esi/model/object_layout.hpp), so that a DataType renamed
// with the same layout is not a change of the object, and a change of a DataType shows on every
// object that uses it. Default values compare by their bytes: DefaultValue 16, DefaultData 1000
// and #x10 are the same default of a UINT.

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include <fmt/format.h>

#include "diff/compare.hpp"
#include "diff/type_names.hpp"
#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::diff_detail {

namespace {

// ---- values --------------------------------------------------------------------------------

// The default (or a limit) of an entry as the bytes a master would read, little-endian as CoE
// transfers them (ETG.1000.6), plus how to show it.
struct EntryValue {
    bool present = false;
    std::optional<std::vector<std::uint8_t>> bytes;  // absent for undecodable data
    std::string raw;                                 // compared when bytes are absent
    std::string display;
    std::optional<Number> number;  // for ordering limits
};

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

int compare_numbers(const Number& a, const Number& b) {
    const bool an = a.negative && a.magnitude != 0;
    const bool bn = b.negative && b.magnitude != 0;
    if (an != bn) return an ? -1 : 1;
    if (a.magnitude == b.magnitude) return 0;
    const bool less = a.magnitude < b.magnitude;
    return (less != an) ? -1 : 1;
}

bool is_mapping_or_assignment(std::uint32_t index) {
    return (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF) || (index >= 0x1C10 && index <= 0x1C2F);
}

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

// ---- defaults and limits -------------------------------------------------------------------

// The range an integer type allows by itself: what an absent MinValue/MaxValue means.
std::optional<Number> type_bound(const ObjectEntry& e, bool is_min) {
    if (!e.basic || !e.basic->is_integer() || e.bit_size == 0 || e.bit_size > 64) return std::nullopt;
    const unsigned bits = static_cast<unsigned>(e.bit_size);
    if (!e.basic->is_signed()) {
        if (is_min) return Number::from_unsigned(0);
        return Number::from_unsigned(bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1);
    }
    const std::uint64_t half = std::uint64_t{1} << (bits - 1);
    return is_min ? Number{half, true} : Number::from_unsigned(half - 1);
}

void compare_limit(Recorder& r, const std::string& path, std::string_view what, bool is_min, const EntryValue& a,
                   const EntryValue& b, const ObjectEntry& ea, const ObjectEntry& eb, SourcePos pa, SourcePos pb) {
    if (same_value(a, b)) return;
    // An absent bound is the type's own bound: declaring MinValue 0 for an unsigned entry narrows nothing.
    const std::optional<Number> old_bound = a.present ? a.number : type_bound(ea, is_min);
    const std::optional<Number> new_bound = b.present ? b.number : type_bound(eb, is_min);
    ChangeKind kind = ChangeKind::object_limits_changed;
    if (old_bound && new_bound) {
        const int c = compare_numbers(*new_bound, *old_bound);
        const bool narrowed = is_min ? c > 0 : c < 0;
        kind = narrowed ? ChangeKind::object_limits_narrowed : ChangeKind::object_limits_widened;
    } else if (!a.present) {
        kind = ChangeKind::object_limits_narrowed;  // a new bound of a type without a known range
    } else if (!b.present) {
        kind = ChangeKind::object_limits_widened;
    }
    r.value(kind, path, what, a.present ? std::optional<std::string>(a.display) : std::nullopt,
            b.present ? std::optional<std::string>(b.display) : std::nullopt, pa, pb);
}

void compare_info_values(Recorder& r, const std::string& p, std::uint32_t object_index, const ObjectEntry& ea,
                         const ObjectEntry& eb, SourcePos pa, SourcePos pb) {
    const ObjectInfo* ia = ea.info;
    const ObjectInfo* ib = eb.info;
    if (ia && ia->pos.known()) pa = ia->pos;
    if (ib && ib->pos.known()) pb = ib->pos;
    const bool mapping = is_mapping_or_assignment(object_index);
    const bool as_hex_a = mapping || (ea.basic && ea.basic->type_class == TypeClass::bit_string);
    const bool as_hex_b = mapping || (eb.basic && eb.basic->type_class == TypeClass::bit_string);
    auto get = [](const ObjectInfo* info, auto member_number, auto member_data, const std::optional<std::string>* string,
                  const ObjectEntry& e, bool as_hex) {
        if (!info) return EntryValue{};
        return value_of(info->*member_number, info->*member_data, string ? *string : std::nullopt, e.bit_size, e.basic, as_hex);
    };
    const EntryValue da =
        get(ia, &ObjectInfo::default_value, &ObjectInfo::default_data, ia ? &ia->default_string : nullptr, ea, as_hex_a);
    const EntryValue db =
        get(ib, &ObjectInfo::default_value, &ObjectInfo::default_data, ib ? &ib->default_string : nullptr, eb, as_hex_b);
    if (!same_value(da, db))
        r.value(mapping ? ChangeKind::pdo_mapping_default_changed : ChangeKind::object_default_changed, child(p, "Default"),
                "default", da.present ? std::optional<std::string>(da.display) : std::nullopt,
                db.present ? std::optional<std::string>(db.display) : std::nullopt, pa, pb);
    compare_limit(r, child(p, "Min"), "minimum", true,
                  get(ia, &ObjectInfo::min_value, &ObjectInfo::min_data, nullptr, ea, as_hex_a),
                  get(ib, &ObjectInfo::min_value, &ObjectInfo::min_data, nullptr, eb, as_hex_b), ea, eb, pa, pb);
    compare_limit(r, child(p, "Max"), "maximum", false,
                  get(ia, &ObjectInfo::max_value, &ObjectInfo::max_data, nullptr, ea, as_hex_a),
                  get(ib, &ObjectInfo::max_value, &ObjectInfo::max_data, nullptr, eb, as_hex_b), ea, eb, pa, pb);
}

// Display name, unit and unmodelled parts of an Info element.
void compare_info_text(Recorder& r, const std::string& p, const ObjectInfo* a, const ObjectInfo* b, SourcePos pa, SourcePos pb) {
    if (a && a->pos.known()) pa = a->pos;
    if (b && b->pos.known()) pb = b->pos;
    r.value(ChangeKind::comment_changed, child(p, "DisplayName"), "DisplayName", a ? a->display_name : std::nullopt,
            b ? b->display_name : std::nullopt, pa, pb);
    r.value(ChangeKind::comment_changed, child(p, "Unit"), "Unit", a ? hex(a->unit, 8) : std::nullopt,
            b ? hex(b->unit, 8) : std::nullopt, pa, pb);
    static const Extras none;
    compare_extras(r, child(p, "Info"), a ? a->extras : none, b ? b->extras : none, pa, pb);
}

// Object/Info/SubItem as written: the names that match them to sub-entries, their unmodelled
// XML, and the values of those that match no sub-entry (values of matched ones were compared
// per sub-entry already).
void compare_info_sub_items(Recorder& r, const std::string& p, const Object& a, const Object& b, const ObjectLayout& la,
                            const ObjectLayout& lb) {
    static const std::vector<ObjectSubItemInfo> none;
    const auto& xs = a.info ? a.info->sub_items : none;
    const auto& ys = b.info ? b.info->sub_items : none;
    if (xs.empty() && ys.empty()) return;
    auto used = [](const ObjectLayout& l, const ObjectSubItemInfo& s) {
        return std::any_of(l.entries.begin(), l.entries.end(), [&](const ObjectEntry& e) { return e.info == &s.info; });
    };
    const std::size_t n = std::max(xs.size(), ys.size());
    for (std::size_t k = 0; k < n; ++k) {
        const ObjectSubItemInfo* x = k < xs.size() ? &xs[k] : nullptr;
        const ObjectSubItemInfo* y = k < ys.size() ? &ys[k] : nullptr;
        const std::string sp = child(p, indexed("Info/SubItem", std::to_string(k + 1)));
        const SourcePos px = x ? x->pos : a.pos;
        const SourcePos py = y ? y->pos : b.pos;
        const bool matched = (x && used(la, *x)) || (y && used(lb, *y));
        if (!matched) {
            // Values no sub-entry reads: compared as written.
            auto spell = [](const ObjectSubItemInfo* s) -> std::optional<std::string> {
                if (!s) return std::nullopt;
                const ObjectInfo& i = s->info;
                std::string out = s->name;
                if (i.default_value) out += " default " + format_decimal(*i.default_value);
                if (i.default_data) out += " default data " + normalized_hex(*i.default_data);
                if (i.default_string) out += " default " + quote(*i.default_string);
                if (i.min_value) out += " min " + format_decimal(*i.min_value);
                if (i.max_value) out += " max " + format_decimal(*i.max_value);
                if (i.min_data) out += " min data " + normalized_hex(*i.min_data);
                if (i.max_data) out += " max data " + normalized_hex(*i.max_data);
                return out;
            };
            r.value(ChangeKind::object_default_changed, sp, "Info/SubItem that matches no sub-entry", spell(x), spell(y), px, py);
            continue;
        }
        if (x && y) {
            r.value(ChangeKind::name_changed, child(sp, "Name"), "Info/SubItem name", x->name, y->name, px, py);
            compare_extras(r, sp, x->extras, y->extras, px, py);
        }
    }
}

// ---- objects -------------------------------------------------------------------------------

std::string object_path(const std::string& path, std::uint32_t index) { return child(path, indexed("Object", hex(index))); }

std::string describe_object(const Object& o) {
    const std::string& name = primary_text(o.names);
    return name.empty() ? fmt::format("object {}", hex(o.index)) : fmt::format("object {} {}", hex(o.index), quote(name));
}

void compare_object(Recorder& r, const std::string& path, const Dictionary* da, const Object& a, const Dictionary* db,
                    const Object& b) {
    const std::string p = object_path(path, a.index);
    compare_texts(r, ChangeKind::name_changed, p, "Name", a.names, b.names, a.pos, b.pos);
    compare_texts(r, ChangeKind::comment_changed, p, "Comment", a.comments, b.comments, a.pos, b.pos);

    const ObjectLayout la = layout_of(da, a);
    const ObjectLayout lb = layout_of(db, b);
    r.value(
        ChangeKind::object_code_changed, child(p, "ObjectCode"),
        [&] { return fmt::format("object code of {}", describe_object(b)); }, std::string(to_string(la.code)),
        std::string(to_string(lb.code)), a.type_pos.known() ? a.type_pos : a.pos, b.type_pos.known() ? b.type_pos : b.pos);
    r.value(
        ChangeKind::object_size_changed, child(p, "BitSize"), [&] { return fmt::format("BitSize of {}", describe_object(b)); },
        std::to_string(a.bit_size), std::to_string(b.bit_size), a.bit_size_pos.known() ? a.bit_size_pos : a.pos,
        b.bit_size_pos.known() ? b.bit_size_pos : b.pos);
    const bool both_var = la.code == ObjectCode::var && lb.code == ObjectCode::var;
    if (!both_var && compare_types(da, a.type, db, b.type) == TypeMatch::spelling)
        r.value(ChangeKind::spelling_changed, child(p, "Type"), "type name (same layout)", a.type, b.type, a.type_pos,
                b.type_pos);

    const ObjectFlags* fa = a.flags ? &*a.flags : nullptr;
    const ObjectFlags* fb = b.flags ? &*b.flags : nullptr;
    compare_flags(r, child(p, "Flags"), fa, fb, a.pos, b.pos);
    compare_info_text(r, p, a.info ? &*a.info : nullptr, b.info ? &*b.info : nullptr, a.pos, b.pos);

    std::set<std::uint32_t> subindices;
    for (const auto& e : la.entries) subindices.insert(e.subindex);
    for (const auto& e : lb.entries) subindices.insert(e.subindex);
    for (std::uint32_t s : subindices) {
        const ObjectEntry* ea = la.entry(s);
        const ObjectEntry* eb = lb.entry(s);
        const std::string ep = both_var ? p : child(path, indexed("Object", entry_key(a.index, s))).str();
        const SourcePos pa = ea && ea->type_item ? ea->type_item->pos : a.pos;
        const SourcePos pb = eb && eb->type_item ? eb->type_item->pos : b.pos;
        if (!ea || !eb) {
            const ObjectEntry& e = ea ? *ea : *eb;
            const std::string value = fmt::format("{} {}", e.name, e.type);
            r.add(ea ? ChangeKind::object_entry_removed : ChangeKind::object_entry_added, ep,
                  ea ? std::optional<std::string>(value) : std::nullopt, eb ? std::optional<std::string>(value) : std::nullopt,
                  pa, pb,
                  fmt::format("sub-index {} {} of {} {}", s, quote(e.name), describe_object(b), ea ? "removed" : "added"));
            continue;
        }
        const auto label = [&] { return both_var ? describe_object(b) : fmt::format("sub-index {} {}", s, quote(eb->name)); };
        if (!both_var)
            r.value(
                ChangeKind::name_changed, child(ep, "Name"), [&] { return fmt::format("name of sub-index {}", s); }, ea->name,
                eb->name, pa, pb);
        switch (compare_types(da, ea->type, db, eb->type)) {
            case TypeMatch::same: break;
            case TypeMatch::spelling:
                r.value(
                    ChangeKind::spelling_changed, child(ep, "Type"), [&] { return fmt::format("type of {}", label()); }, ea->type,
                    eb->type, pa, pb);
                break;
            case TypeMatch::different:
                r.value(
                    ChangeKind::object_entry_type_changed, child(ep, "Type"), [&] { return fmt::format("type of {}", label()); },
                    ea->type, eb->type, pa, pb);
                break;
        }
        if (!both_var) {
            r.value(
                ChangeKind::object_entry_type_changed, child(ep, "BitSize"),
                [&] { return fmt::format("BitSize of {}", label()); }, std::to_string(ea->bit_size), std::to_string(eb->bit_size),
                pa, pb);
            r.value(
                ChangeKind::object_entry_offset_changed, child(ep, "BitOffs"),
                [&] { return fmt::format("BitOffs of {}", label()); }, std::to_string(ea->bit_offset),
                std::to_string(eb->bit_offset), pa, pb);
            // Flags of their own (from the DataType SubItem); flags inherited from the object were compared above.
            if (ea->flags != fa || eb->flags != fb) compare_flags(r, child(ep, "Flags"), ea->flags, eb->flags, pa, pb);
            if (ea->info != (a.info ? &*a.info : nullptr) || eb->info != (b.info ? &*b.info : nullptr))
                compare_info_text(r, ep, ea->info, eb->info, pa, pb);
        }
        compare_info_values(r, ep, a.index, *ea, *eb, a.pos, b.pos);
    }
    compare_info_sub_items(r, p, a, b, la, lb);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

// ---- data types ----------------------------------------------------------------------------

std::string names_text(const Names& names) {
    std::string out;
    for (const auto& n : names) out += (n.lcid ? std::to_string(*n.lcid) : std::string()) + "=" + n.text + ";";
    return out;
}

bool same_extras(const Extras& a, const Extras& b) {
    std::vector<Change> scratch;
    Recorder probe(scratch);
    compare_extras(probe, "", a, b, {}, {});
    return scratch.empty();
}

// What differs between two DataTypes of the same name: semantic differences (layout, bounds,
// enum values) and textual ones (comments, display names, enum texts).
void data_type_differences(const DataType& a, const DataType& b, std::vector<std::string>& semantic,
                           std::vector<std::string>& textual) {
    auto diff = [](std::vector<std::string>& out, std::string what, const std::optional<std::string>& x,
                   const std::optional<std::string>& y) {
        if (x != y) out.push_back(fmt::format("{} {} -> {}", what, x.value_or("(none)"), y.value_or("(none)")));
    };
    diff(semantic, "Index", hex(a.index), hex(b.index));
    const auto base_a = a.base_type ? std::optional<std::string>(normalized_type_name(*a.base_type)) : std::nullopt;
    const auto base_b = b.base_type ? std::optional<std::string>(normalized_type_name(*b.base_type)) : std::nullopt;
    diff(semantic, "BaseType", base_a, base_b);
    if (base_a == base_b) diff(textual, "BaseType spelling", a.base_type, b.base_type);
    diff(semantic, "BitSize", std::to_string(a.bit_size), std::to_string(b.bit_size));
    const std::size_t arrays = std::max(a.array_info.size(), b.array_info.size());
    for (std::size_t i = 0; i < arrays; ++i) {
        auto spell = [](const std::vector<ArrayInfo>& v, std::size_t k) -> std::optional<std::string> {
            if (k >= v.size()) return std::nullopt;
            return fmt::format("[{}, {} elements]", v[k].lower_bound, v[k].elements);
        };
        diff(semantic, fmt::format("ArrayInfo {}", i + 1), spell(a.array_info, i), spell(b.array_info, i));
    }
    const std::size_t items = std::max(a.sub_items.size(), b.sub_items.size());
    for (std::size_t i = 0; i < items; ++i) {
        const DataTypeSubItem* x = i < a.sub_items.size() ? &a.sub_items[i] : nullptr;
        const DataTypeSubItem* y = i < b.sub_items.size() ? &b.sub_items[i] : nullptr;
        const std::string label = fmt::format("SubItem {}", i + 1);
        if (!x || !y) {
            const DataTypeSubItem& s = x ? *x : *y;
            semantic.push_back(
                fmt::format("{} {} ({} {}) {}", label, quote(s.name), s.type, s.bit_size, x ? "removed" : "added"));
            continue;
        }
        diff(semantic, label + " SubIdx", dec(x->subindex), dec(y->subindex));
        diff(textual, label + " Name", x->name, y->name);
        const TypeMatch tm = compare_type_names(x->type, y->type);
        if (tm == TypeMatch::different)
            diff(semantic, label + " Type", x->type, y->type);
        else if (tm == TypeMatch::spelling)
            diff(textual, label + " Type spelling", x->type, y->type);
        diff(semantic, label + " BitSize", std::to_string(x->bit_size), std::to_string(y->bit_size));
        diff(semantic, label + " BitOffs", std::to_string(x->bit_offset), std::to_string(y->bit_offset));
        const EntryValue dx = value_of(x->default_value, x->default_data, x->default_string, x->bit_size, nullptr, false);
        const EntryValue dy = value_of(y->default_value, y->default_data, y->default_string, y->bit_size, nullptr, false);
        if (!same_value(dx, dy))
            semantic.push_back(label + " default " + (dx.present ? dx.display : "(none)") + " -> " +
                               (dy.present ? dy.display : "(none)"));
        const EntryValue nx = value_of(x->min_value, std::nullopt, std::nullopt, x->bit_size, nullptr, false);
        const EntryValue ny = value_of(y->min_value, std::nullopt, std::nullopt, y->bit_size, nullptr, false);
        if (!same_value(nx, ny))
            semantic.push_back(label + " minimum " + (nx.present ? nx.display : "(none)") + " -> " +
                               (ny.present ? ny.display : "(none)"));
        const EntryValue mx = value_of(x->max_value, std::nullopt, std::nullopt, x->bit_size, nullptr, false);
        const EntryValue my = value_of(y->max_value, std::nullopt, std::nullopt, y->bit_size, nullptr, false);
        if (!same_value(mx, my))
            semantic.push_back(label + " maximum " + (mx.present ? mx.display : "(none)") + " -> " +
                               (my.present ? my.display : "(none)"));
        {
            std::vector<Change> scratch;
            Recorder probe(scratch);
            compare_flags(probe, "", x->flags ? &*x->flags : nullptr, y->flags ? &*y->flags : nullptr, {}, {});
            for (const auto& c : scratch)
                (c.change_class == ChangeClass::cosmetic ? textual : semantic).push_back(label + " " + c.message);
        }
        if (names_text(x->display_names) != names_text(y->display_names)) textual.push_back(label + " DisplayName");
        if (names_text(x->comments) != names_text(y->comments)) textual.push_back(label + " Comment");
        if (!same_extras(x->extras, y->extras)) textual.push_back(label + " unmodelled XML");
    }
    const std::size_t enums = std::max(a.enums.size(), b.enums.size());
    for (std::size_t i = 0; i < enums; ++i) {
        const EnumValue* x = i < a.enums.size() ? &a.enums[i] : nullptr;
        const EnumValue* y = i < b.enums.size() ? &b.enums[i] : nullptr;
        const std::string label = fmt::format("Enum {}", i + 1);
        if (!x || !y) {
            semantic.push_back(fmt::format("{} {} {}", label, format_decimal((x ? x : y)->value), x ? "removed" : "added"));
            continue;
        }
        if (!(x->value == y->value))
            semantic.push_back(fmt::format("{} value {} -> {}", label, format_decimal(x->value), format_decimal(y->value)));
        if (names_text(x->texts) != names_text(y->texts)) textual.push_back(label + " Text");
        if (names_text(x->comments) != names_text(y->comments)) textual.push_back(label + " Comment");
    }
    if (names_text(a.comments) != names_text(b.comments)) textual.push_back("Comment");
    if (!same_extras(a.extras, b.extras)) textual.push_back("unmodelled XML");
}

std::string summary(const std::vector<std::string>& items) {
    constexpr std::size_t shown = 4;
    std::string out;
    for (std::size_t i = 0; i < items.size() && i < shown; ++i) out += (i ? "; " : "") + items[i];
    if (items.size() > shown) out += fmt::format("; and {} more", items.size() - shown);
    return out;
}

void compare_data_types(Recorder& r, const std::string& path, const Dictionary* a, const Dictionary* b, SourcePos old_parent,
                        SourcePos new_parent) {
    std::map<std::string, std::vector<const DataType*>> ta;
    std::map<std::string, std::vector<const DataType*>> tb;
    if (a)
        for (const auto& t : a->data_types) ta[normalized_type_name(t.name)].push_back(&t);
    if (b)
        for (const auto& t : b->data_types) tb[normalized_type_name(t.name)].push_back(&t);
    std::set<std::string> names;
    for (const auto& [k, v] : ta) names.insert(k);
    for (const auto& [k, v] : tb) names.insert(k);
    for (const auto& name : names) {
        const auto& la = ta[name];
        const auto& lb = tb[name];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const DataType* x = i < la.size() ? la[i] : nullptr;
            const DataType* y = i < lb.size() ? lb[i] : nullptr;
            const std::string p = child(path, indexed("DataType", n > 1 ? fmt::format("{}#{}", name, i + 1) : name));
            if (!x) {
                r.add(ChangeKind::data_type_added, p, std::nullopt, fmt::format("{} bits", y->bit_size), old_parent, y->pos,
                      fmt::format("DataType {} added", y->name));
                continue;
            }
            if (!y) {
                r.add(ChangeKind::data_type_removed, p, fmt::format("{} bits", x->bit_size), std::nullopt, x->pos, new_parent,
                      fmt::format("DataType {} removed", x->name));
                continue;
            }
            if (canonical_type_name(x->name) != canonical_type_name(y->name))
                r.value(ChangeKind::spelling_changed, child(p, "Name"), "DataType name", x->name, y->name, x->name_pos,
                        y->name_pos);
            std::vector<std::string> semantic;
            std::vector<std::string> textual;
            data_type_differences(*x, *y, semantic, textual);
            if (!semantic.empty())
                r.add(ChangeKind::data_type_changed, p, fmt::format("{} bits", x->bit_size), fmt::format("{} bits", y->bit_size),
                      x->pos, y->pos, fmt::format("DataType {} changed: {}", y->name, summary(semantic)));
            if (!textual.empty())
                r.add(ChangeKind::data_type_text_changed, p, std::nullopt, std::nullopt, x->pos, y->pos,
                      fmt::format("DataType {} texts changed: {}", y->name, summary(textual)));
        }
    }
}

}  // namespace

void compare_dictionaries(Recorder& r, const std::string& path, const Dictionary* a, const Dictionary* b, SourcePos old_parent,
                          SourcePos new_parent) {
    if (!a && !b) return;
    compare_data_types(r, path, a, b, old_parent, new_parent);

    std::map<std::uint32_t, std::vector<const Object*>> oa;
    std::map<std::uint32_t, std::vector<const Object*>> ob;
    if (a)
        for (const auto& o : a->objects) oa[o.index].push_back(&o);
    if (b)
        for (const auto& o : b->objects) ob[o.index].push_back(&o);
    std::set<std::uint32_t> indices;
    for (const auto& [k, v] : oa) indices.insert(k);
    for (const auto& [k, v] : ob) indices.insert(k);
    for (std::uint32_t index : indices) {
        const auto& la = oa[index];
        const auto& lb = ob[index];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const Object* x = i < la.size() ? la[i] : nullptr;
            const Object* y = i < lb.size() ? lb[i] : nullptr;
            if (x && y) {
                compare_object(r, path, a, *x, b, *y);
                continue;
            }
            const Object& o = x ? *x : *y;
            const std::string value = fmt::format("{} {}", o.type, o.bit_size);
            r.add(x ? ChangeKind::object_removed : ChangeKind::object_added, object_path(path, index),
                  x ? std::optional<std::string>(value) : std::nullopt, y ? std::optional<std::string>(value) : std::nullopt,
                  x ? x->pos : old_parent, y ? y->pos : new_parent,
                  fmt::format("{} {}", describe_object(o), x ? "removed" : "added"));
        }
    }
    static const Extras none;
    compare_extras(r, path, a ? a->extras : none, b ? b->extras : none, old_parent, new_parent);
}

}  // namespace esi::diff_detail
