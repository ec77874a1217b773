// The object dictionary. Objects pair up by index and DataTypes by (canonical) name: their order
// in the file has no meaning (ETG.2000 Dictionary). Objects are compared the way a master sees
// them over SDO, sub-entry by sub-entry (esi/model/object_layout.hpp), so that a DataType renamed
// with the same layout is not a change of the object, and a change of a DataType shows on every
// object that uses it. Default values compare by their bytes: DefaultValue 16, DefaultData 1000
// and #x10 are the same default of a UINT. DataTypes and entry values have files of their own
// (compare_dictionary.hpp).

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "diff/compare_dictionary.hpp"
#include "diff/type_names.hpp"
#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::diff_detail {

namespace {

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
    auto get = [](const ObjectInfo* info, auto member_number, auto member_data, const RareOptional<std::string>* string,
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
