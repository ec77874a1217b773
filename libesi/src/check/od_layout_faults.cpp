#include "check/od_layout_faults.hpp"

#include <algorithm>
#include <functional>
#include <vector>

namespace esi::rules {

namespace {

// The SubItems that take part in overlaps: sub-indices with a size.
bool is_placed_subindex(const DataTypeSubItem& item) { return item.bit_size > 0 && item.subindex.has_value(); }

// Whether the placed SubItems of `items` come by BitOffs as listed.
bool placed_by_offset(const std::vector<DataTypeSubItem>& items) {
    const DataTypeSubItem* previous = nullptr;
    for (const DataTypeSubItem& item : items) {
        if (!is_placed_subindex(item)) continue;
        if (previous && item.bit_offset < previous->bit_offset) return false;
        previous = &item;
    }
    return true;
}

// Records the overlaps among the placed SubItems of `items`, which come by BitOffs. (A loop that
// skips the others rather than a filter view: clang rejects std::views::filter over libstdc++ 12.)
template <class Items>
void find_overlaps(const Items& items, LayoutFaults& out) {
    const DataTypeSubItem* reach = nullptr;  // the item that extends furthest so far
    for (const DataTypeSubItem& item : items) {
        if (!is_placed_subindex(item)) continue;
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
    // SubItems are listed by BitOffs as a rule, and are then walked where they are; only a list
    // out of order is copied and sorted (stably: among equal offsets the first listed comes first).
    if (placed_by_offset(type.sub_items)) {
        find_overlaps(type.sub_items, out);
        return out;
    }
    std::vector<std::reference_wrapper<const DataTypeSubItem>> sorted;
    for (const DataTypeSubItem& item : type.sub_items)
        if (is_placed_subindex(item)) sorted.emplace_back(item);
    std::ranges::stable_sort(sorted, by_offset);
    find_overlaps(sorted, out);
    return out;
}

}  // namespace esi::rules
