// DataTypes of the object dictionary. They pair up by (canonical) name, as objects refer to them;
// a DataType's changes are summed up in one change for its layout and values and one for its
// texts, since every object that uses it shows the effect sub-entry by sub-entry.

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "diff/compare_dictionary.hpp"
#include "diff/type_names.hpp"

namespace esi::diff_detail {

namespace {

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

}  // namespace

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

}  // namespace esi::diff_detail
