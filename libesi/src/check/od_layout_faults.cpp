#include "check/od_layout_faults.hpp"

#include <algorithm>
#include <vector>

namespace esi::rules {

LayoutFaults layout_faults(const DataType& type) {
    LayoutFaults out;
    for (const auto& item : type.sub_items) {
        if (item.bit_size == 0 || type.bit_size == 0 || item.bit_offset + item.bit_size <= type.bit_size) continue;
        out.past_end = &item;
        break;
    }
    std::vector<const DataTypeSubItem*> items;
    for (const auto& item : type.sub_items)
        if (item.bit_size > 0 && item.subindex) items.push_back(&item);
    std::stable_sort(items.begin(), items.end(),
                     [](const DataTypeSubItem* a, const DataTypeSubItem* b) { return a->bit_offset < b->bit_offset; });
    const DataTypeSubItem* reach = nullptr;  // the item that extends furthest so far
    for (const DataTypeSubItem* item : items) {
        if (reach && item->bit_offset < reach->bit_offset + reach->bit_size) {
            if (!out.overlapping) {
                out.overlapping = item;
                out.overlapped = reach;
            }
            ++out.overlap_count;
        }
        if (!reach || item->bit_offset + item->bit_size > reach->bit_offset + reach->bit_size) reach = item;
    }
    return out;
}

}  // namespace esi::rules
