#pragma once
// What is wrong with the layout of a record DataType (ETG.2000 DataTypeType: SubItems placed by
// BitOffs and BitSize inside the type's BitSize): a SubItem that ends past the type, and
// sub-indices that share bits. od-subitem-layout reports them, od-layout-complete-access where
// complete access writes such a type, and od-bitsize leaves their consequences to them.

#include <cstddef>

#include "esi/model/dictionary.hpp"

namespace esi::rules {

struct LayoutFaults {
    const DataTypeSubItem* past_end = nullptr;    // the first SubItem (in the file) ending past BitSize
    const DataTypeSubItem* overlapping = nullptr;  // the first sub-index (by BitOffs) overlapping another
    const DataTypeSubItem* overlapped = nullptr;   // the sub-index it overlaps
    std::size_t overlap_count = 0;                 // sub-indices overlapping others

    [[nodiscard]] bool any() const { return past_end || overlapping; }
};

// Overlaps count only between sub-indices (SubItems with SubIdx): SubItems without SubIdx are
// members of a structure, where SoE dictionaries lay out unions on purpose (Beckhoff
// DT_IDN_..._Union).
[[nodiscard]] LayoutFaults layout_faults(const DataType& type);

}  // namespace esi::rules
