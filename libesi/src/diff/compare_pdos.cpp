// PDOs and their entries. PDOs pair up by direction and index; their order in the file has no
// meaning except among the PDOs assigned to the same SyncManager, whose order is the order of
// their data in the process image (ETG.1000.6 0x1C1x). Entries are the process-image layout of
// the PDO, so their order is compared: they are aligned by (index, subindex) and whatever is not
// in the longest common subsequence was moved, replaced, added or removed.

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "diff/compare.hpp"
#include "diff/sequence.hpp"
#include "diff/type_names.hpp"

namespace esi::diff_detail {

namespace {

using EntryKey = std::pair<std::uint32_t, std::uint32_t>;

EntryKey key_of(const PdoEntry& e) { return {e.index, e.is_padding() ? 0u : e.effective_subindex()}; }

// "Entry[#x7000:01]"; padding has no identity of its own and is named by its position (from 1).
std::string entry_path(const std::string& pdo_path, const PdoEntry& e, std::size_t position) {
    if (e.is_padding()) return child(pdo_path, indexed("Entry", std::to_string(position + 1)));
    return child(pdo_path, indexed("Entry", entry_key(e.index, e.effective_subindex())));
}

std::string describe_entry(const PdoEntry& e) {
    const std::string& name = primary_text(e.names);
    if (e.is_padding())
        return name.empty() ? fmt::format("padding of {} bits", e.bit_len)
                            : fmt::format("{} (index 0, {} bits)", quote(name), e.bit_len);
    return name.empty() ? entry_key(e.index, e.effective_subindex())
                        : fmt::format("{} {}", entry_key(e.index, e.effective_subindex()), quote(name));
}

std::string entry_value(const PdoEntry& e) {
    if (e.is_padding()) return fmt::format("padding {} bits", e.bit_len);
    return fmt::format("{} {} bits{}", entry_key(e.index, e.effective_subindex()), e.bit_len,
                       e.data_type ? " " + *e.data_type : std::string());
}

void compare_entry_fields(Recorder& r, const std::string& p, const PdoEntry& a, const PdoEntry& b) {
    const auto label = [&] { return describe_entry(b); };
    r.value(
        ChangeKind::pdo_entry_bit_len_changed, child(p, "BitLen"), [&] { return fmt::format("BitLen of entry {}", label()); },
        dec(a.bit_len), dec(b.bit_len), a.bit_len_pos.known() ? a.bit_len_pos : a.pos,
        b.bit_len_pos.known() ? b.bit_len_pos : b.pos);
    const SourcePos ta = a.data_type_pos.known() ? a.data_type_pos : a.pos;
    const SourcePos tb = b.data_type_pos.known() ? b.data_type_pos : b.pos;
    if (a.data_type && b.data_type) {
        switch (compare_type_names(*a.data_type, *b.data_type)) {
            case TypeMatch::same: break;
            case TypeMatch::spelling:
                r.value(
                    ChangeKind::spelling_changed, child(p, "DataType"),
                    [&] { return fmt::format("DataType of entry {}", label()); }, a.data_type, b.data_type, ta, tb);
                break;
            case TypeMatch::different:
                r.value(
                    ChangeKind::pdo_entry_data_type_changed, child(p, "DataType"),
                    [&] { return fmt::format("DataType of entry {}", label()); }, a.data_type, b.data_type, ta, tb);
                break;
        }
    } else {
        r.value(
            ChangeKind::pdo_entry_data_type_declared, child(p, "DataType"),
            [&] { return fmt::format("DataType of entry {}", label()); }, a.data_type, b.data_type, ta, tb);
    }
    r.value(ChangeKind::pdo_entry_attribute_changed, child(p, "DataType@DScale"), "DScale", a.data_type_dscale,
            b.data_type_dscale, ta, tb);
    r.value(ChangeKind::pdo_entry_attribute_changed, child(p, "DataType@SwapData"), "SwapData", a.data_type_swap_data,
            b.data_type_swap_data, ta, tb);
    r.value(ChangeKind::pdo_entry_attribute_changed, attr(p, "Fixed"), "Fixed", flag(a.fixed), flag(b.fixed), a.pos, b.pos);
    r.value(ChangeKind::pdo_entry_attribute_changed, child(p, "Index@DependOnSlot"), "Index@DependOnSlot",
            flag(a.index_depend_on_slot), flag(b.index_depend_on_slot), a.pos, b.pos);
    r.value(ChangeKind::pdo_entry_attribute_changed, child(p, "Index@DependOnSlotGroup"), "Index@DependOnSlotGroup",
            flag(a.index_depend_on_slot_group), flag(b.index_depend_on_slot_group), a.pos, b.pos);
    compare_texts(r, ChangeKind::name_changed, p, "Name", a.names, b.names, a.pos, b.pos);
    r.value(ChangeKind::comment_changed, child(p, "Comment"), "Comment", a.comment, b.comment, a.pos, b.pos);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

void compare_entries(Recorder& r, const std::string& pdo_path, const Pdo& a, const Pdo& b) {
    std::vector<EntryKey> ka;
    std::vector<EntryKey> kb;
    for (const auto& e : a.entries) ka.push_back(key_of(e));
    for (const auto& e : b.entries) kb.push_back(key_of(e));
    const Alignment alignment = align(
        ka, kb, [](const EntryKey& k) { return k.first != 0; }, true);

    // Report in the order of the new PDO so that output reads top to bottom.
    std::vector<Alignment::Pair> pairs = alignment.pairs;
    std::sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.new_index < y.new_index; });
    for (const auto& pair : pairs) {
        const PdoEntry& x = a.entries[pair.old_index];
        const PdoEntry& y = b.entries[pair.new_index];
        const std::string p = entry_path(pdo_path, x, pair.old_index);
        if (pair.how == Alignment::Pair::How::moved) {
            r.add(
                ChangeKind::pdo_entry_moved, p, fmt::format("position {}", pair.old_index + 1),
                fmt::format("position {}", pair.new_index + 1), x.pos, y.pos,
                fmt::format("entry {} moved from position {} to {}", describe_entry(y), pair.old_index + 1, pair.new_index + 1));
        } else if (pair.how == Alignment::Pair::How::replaced) {
            r.add(ChangeKind::pdo_entry_index_changed, child(p, "Index"), entry_value(x), entry_value(y), x.pos, y.pos,
                  fmt::format("entry {} of {} now maps {} instead of {}", pair.new_index + 1, a.element_name(), describe_entry(y),
                              describe_entry(x)));
        }
        compare_entry_fields(r, pair.how == Alignment::Pair::How::replaced ? entry_path(pdo_path, y, pair.new_index) : p, x, y);
    }
    for (std::size_t j : alignment.added) {
        const PdoEntry& y = b.entries[j];
        r.add(ChangeKind::pdo_entry_added, entry_path(pdo_path, y, j), std::nullopt, entry_value(y), a.pos, y.pos,
              fmt::format("entry {} added at position {}", describe_entry(y), j + 1));
    }
    for (std::size_t i : alignment.removed) {
        const PdoEntry& x = a.entries[i];
        r.add(ChangeKind::pdo_entry_removed, entry_path(pdo_path, x, i), entry_value(x), std::nullopt, x.pos, b.pos,
              fmt::format("entry {} removed from position {}", describe_entry(x), i + 1));
    }
}

std::string exclude_key(const PdoExclude& e) {
    std::string k = hex(e.index);
    if (e.depend_on_slot.value_or(false)) k += " DependOnSlot";
    if (e.depend_on_slot_group.value_or(false)) k += " DependOnSlotGroup";
    return k;
}

void compare_pdo(Recorder& r, const std::string& p, const Pdo& a, const Pdo& b) {
    compare_texts(r, ChangeKind::name_changed, p, "Name", a.names, b.names, a.pos, b.pos);
    // The default SM assignment: gaining, losing or changing it changes the default process image.
    r.value(ChangeKind::pdo_sm_changed, attr(p, "Sm"), "default SyncManager", dec(a.sm), dec(b.sm), a.pos, b.pos);
    if (a.fixed.value_or(false) != b.fixed.value_or(false))
        r.value(b.fixed.value_or(false) ? ChangeKind::pdo_fixed_set : ChangeKind::pdo_fixed_cleared, attr(p, "Fixed"), "Fixed",
                flag(a.fixed), flag(b.fixed), a.pos, b.pos);
    if (a.mandatory.value_or(false) != b.mandatory.value_or(false))
        r.value(b.mandatory.value_or(false) ? ChangeKind::pdo_mandatory_set : ChangeKind::pdo_mandatory_cleared,
                attr(p, "Mandatory"), "Mandatory", flag(a.mandatory), flag(b.mandatory), a.pos, b.pos);
    const auto attribute = [&](std::string_view name, std::optional<std::string> x, std::optional<std::string> y) {
        r.value(ChangeKind::pdo_attribute_changed, attr(p, name), name, x, y, a.pos, b.pos);
    };
    attribute("Virtual", flag(a.is_virtual), flag(b.is_virtual));
    attribute("Su", dec(a.su), dec(b.su));
    attribute("PdoOrder", dec(a.pdo_order), dec(b.pdo_order));
    attribute("OSFac", dec(a.os_fac), dec(b.os_fac));
    attribute("OSMin", dec(a.os_min), dec(b.os_min));
    attribute("OSMax", dec(a.os_max), dec(b.os_max));
    attribute("OSIndexInc", dec(a.os_index_inc), dec(b.os_index_inc));
    attribute("OverwrittenByModule", flag(a.overwritten_by_module), flag(b.overwritten_by_module));
    attribute("SRA_Parameter", flag(a.sra_parameter), flag(b.sra_parameter));
    attribute("SafetyPdoType", a.safety_pdo_type, b.safety_pdo_type);
    attribute("SafetyConnNumber", dec(a.safety_conn_number), dec(b.safety_conn_number));
    r.value(ChangeKind::pdo_attribute_changed, child(p, "Index@DependOnSlot"), "Index@DependOnSlot", flag(a.index_depend_on_slot),
            flag(b.index_depend_on_slot), a.index_pos, b.index_pos);
    r.value(ChangeKind::pdo_attribute_changed, child(p, "Index@DependOnSlotGroup"), "Index@DependOnSlotGroup",
            flag(a.index_depend_on_slot_group), flag(b.index_depend_on_slot_group), a.index_pos, b.index_pos);

    // Excludes and ExcludedSm are sets: order carries no meaning.
    std::map<std::string, const PdoExclude*> xa;
    std::map<std::string, const PdoExclude*> xb;
    for (const auto& e : a.excludes) xa.emplace(exclude_key(e), &e);
    for (const auto& e : b.excludes) xb.emplace(exclude_key(e), &e);
    for (const auto& [k, e] : xb)
        if (!xa.count(k))
            r.add(ChangeKind::pdo_exclude_added, child(p, indexed("Exclude", k)), std::nullopt, k, a.pos, e->pos,
                  fmt::format("{} {} now excludes PDO {}", a.element_name(), hex(b.index), k));
    for (const auto& [k, e] : xa)
        if (!xb.count(k))
            r.add(ChangeKind::pdo_exclude_removed, child(p, indexed("Exclude", k)), k, std::nullopt, e->pos, b.pos,
                  fmt::format("{} {} no longer excludes PDO {}", a.element_name(), hex(a.index), k));
    std::vector<std::uint32_t> sa = a.excluded_sms;
    std::vector<std::uint32_t> sb = b.excluded_sms;
    std::sort(sa.begin(), sa.end());
    std::sort(sb.begin(), sb.end());
    for (std::uint32_t sm : sb)
        if (!std::binary_search(sa.begin(), sa.end(), sm))
            r.add(ChangeKind::pdo_exclude_added, child(p, indexed("ExcludedSm", std::to_string(sm))), std::nullopt,
                  std::to_string(sm), a.pos, b.pos,
                  fmt::format("{} {} may no longer be assigned to SyncManager {}", a.element_name(), hex(b.index), sm));
    for (std::uint32_t sm : sa)
        if (!std::binary_search(sb.begin(), sb.end(), sm))
            r.add(ChangeKind::pdo_exclude_removed, child(p, indexed("ExcludedSm", std::to_string(sm))), std::to_string(sm),
                  std::nullopt, a.pos, b.pos,
                  fmt::format("{} {} may now be assigned to SyncManager {}", a.element_name(), hex(a.index), sm));

    compare_entries(r, p, a, b);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

std::string describe_pdo(const Pdo& p) {
    const std::string& name = primary_text(p.names);
    std::string out = fmt::format("{} {}", p.element_name(), hex(p.index));
    if (!name.empty()) out += " " + quote(name);
    out += fmt::format(" ({} {}, {} bits{})", p.entries.size(), p.entries.size() == 1 ? "entry" : "entries", p.bit_size(),
                       p.sm ? fmt::format(", Sm {}", *p.sm) : std::string());
    return out;
}

}  // namespace

void compare_pdos(Recorder& r, const std::string& path, const std::vector<Pdo>& a, const std::vector<Pdo>& b,
                  SourcePos old_parent, SourcePos new_parent) {
    // Pair by index; the k-th PDO with a given index pairs with the k-th in the other file.
    std::map<std::uint32_t, std::vector<std::size_t>> ia;
    std::map<std::uint32_t, std::vector<std::size_t>> ib;
    for (std::size_t i = 0; i < a.size(); ++i) ia[a[i].index].push_back(i);
    for (std::size_t j = 0; j < b.size(); ++j) ib[b[j].index].push_back(j);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    std::vector<std::size_t> removed;
    std::vector<std::size_t> added;
    for (const auto& [index, list] : ia) {
        const auto it = ib.find(index);
        const std::size_t both = it == ib.end() ? 0 : std::min(list.size(), it->second.size());
        for (std::size_t k = 0; k < list.size(); ++k) {
            if (k < both)
                pairs.emplace_back(list[k], it->second[k]);
            else
                removed.push_back(list[k]);
        }
    }
    for (const auto& [index, list] : ib) {
        const auto it = ia.find(index);
        const std::size_t both = it == ia.end() ? 0 : std::min(list.size(), it->second.size());
        for (std::size_t k = both; k < list.size(); ++k) added.push_back(list[k]);
    }

    auto pdo_path = [&](const Pdo& p, const std::vector<std::size_t>& same_index, std::size_t position) -> std::string {
        std::string key = hex(p.index);
        if (same_index.size() > 1) key += fmt::format("#{}", position + 1);
        return child(path, indexed(p.element_name(), key));
    };
    auto position_in = [](const std::vector<std::size_t>& list, std::size_t i) {
        return static_cast<std::size_t>(std::find(list.begin(), list.end(), i) - list.begin());
    };

    for (const auto& [i, j] : pairs) {
        const auto& list = ia[a[i].index];
        compare_pdo(r, pdo_path(a[i], list, position_in(list, i)), a[i], b[j]);
    }
    for (std::size_t j : added) {
        const Pdo& y = b[j];
        const auto& list = ib[y.index];
        r.add(y.sm ? ChangeKind::pdo_added_assigned : ChangeKind::pdo_added, pdo_path(y, list, position_in(list, j)),
              std::nullopt, describe_pdo(y), old_parent, y.pos,
              y.sm ? fmt::format("{} added and assigned to SyncManager {} by default", describe_pdo(y), *y.sm)
                   : fmt::format("{} added", describe_pdo(y)));
    }
    for (std::size_t i : removed) {
        const Pdo& x = a[i];
        const auto& list = ia[x.index];
        r.add(ChangeKind::pdo_removed, pdo_path(x, list, position_in(list, i)), describe_pdo(x), std::nullopt, x.pos, new_parent,
              fmt::format("{} removed", describe_pdo(x)));
    }

    // Order of the PDOs assigned to each SyncManager, among those present in both files with the
    // same assignment (additions, removals and re-assignments are reported above).
    std::map<std::uint32_t, std::vector<std::uint32_t>> order_a;
    std::map<std::uint32_t, std::vector<std::uint32_t>> order_b;
    std::vector<std::pair<std::size_t, std::size_t>> by_old = pairs;
    std::sort(by_old.begin(), by_old.end());
    for (const auto& [i, j] : by_old)
        if (a[i].sm && a[i].sm == b[j].sm) order_a[*a[i].sm].push_back(a[i].index);
    std::vector<std::pair<std::size_t, std::size_t>> by_new = pairs;
    std::sort(by_new.begin(), by_new.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
    for (const auto& [i, j] : by_new)
        if (a[i].sm && a[i].sm == b[j].sm) order_b[*b[j].sm].push_back(b[j].index);
    for (const auto& [sm, list] : order_a) {
        const auto& other = order_b[sm];
        if (list == other) continue;
        auto spell = [](const std::vector<std::uint32_t>& l) {
            std::string s;
            for (std::uint32_t index : l) s += (s.empty() ? "" : " ") + hex(index);
            return s;
        };
        const Pdo* first = nullptr;
        for (const auto& p : b)
            if (p.sm == sm) {
                first = &p;
                break;
            }
        r.add(ChangeKind::sm_assignment_order_changed,
              child(path, indexed("Sm", std::to_string(sm))).str() + "/" +
                  (a.empty() ? "Pdo" : std::string(a.front().element_name())) + "Assignment",
              spell(list), spell(other), old_parent, first ? first->pos : new_parent,
              fmt::format("order of the PDOs assigned to SyncManager {} changed from {} to {}", sm, spell(list), spell(other)));
    }
}

}  // namespace esi::diff_detail
