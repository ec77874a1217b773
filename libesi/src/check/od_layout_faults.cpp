#include "check/od_layout_faults.hpp"

#include <algorithm>
#include <ranges>
#include <vector>

namespace esi::rules {

namespace {

// The SubItems that take part in overlaps: sub-indices with a size.
bool is_placed_subindex(const DataTypeSubItem& item) { return item.bit_size > 0 && item.subindex.has_value(); }

// Records the overlaps among `items`, which come by BitOffs.
template <class Items>
void find_overlaps(Items&& items, LayoutFaults& out) {
    const DataTypeSubItem* reach = nullptr;  // the item that extends furthest so far
    for (const DataTypeSubItem& item : items) {
        if (reach && item.bit_offset < reach->bit_offset + reach->bit_size) {
            if (!out.overlapping) {
                out.overlapping = &item;
                out.overlapped = reach;
            }
            ++out.overlap_count;
        }
        if (!reach || item.bit_offset + item.bit_size > reach->bit_offset + reach->bit_size) reach = &item;
    }
}

}  // namespace

LayoutFaults layout_faults(const DataType& type) {
    LayoutFaults out;
    for (const auto& item : type.sub_items) {
        if (item.bit_size == 0 || type.bit_size == 0 || item.bit_offset + item.bit_size <= type.bit_size) continue;
        out.past_end = &item;
        break;
    }
    const auto by_offset = [](const DataTypeSubItem& a, const DataTypeSubItem& b) { return a.bit_offset < b.bit_offset; };
    auto placed = type.sub_items | std::views::filter(is_placed_subindex);
    // SubItems are listed by BitOffs as a rule, and are then walked where they are; only a list
    // out of order is copied and sorted (stably: among equal offsets the first listed comes first).
    if (std::ranges::is_sorted(placed, by_offset)) {
        find_overlaps(placed, out);
        return out;
    }
    std::vector<std::reference_wrapper<const DataTypeSubItem>> sorted(placed.begin(), placed.end());
    std::ranges::stable_sort(sorted, by_offset);
    find_overlaps(sorted, out);
    return out;
}

}  // namespace esi::rules
