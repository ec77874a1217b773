#include "check/od_type_sizes.hpp"

#include "check/od_layout_faults.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {
// The two 16-bit length words at bits 0 and 16 of an SoE list record.
bool has_list_header(const DataType& record, const DataTypeSubItem& elements) {
    bool current = false;
    bool maximum = false;
    for (const auto& item : record.sub_items) {
        if (&item == &elements || item.bit_size != 16) continue;
        current = current || item.bit_offset == 0;
        maximum = maximum || item.bit_offset == 16;
    }
    return current && maximum && elements.bit_offset == 32;
}
}  // namespace

DataTypeSizes::DataTypeSizes(const Dictionary& dictionary, const TypeIndex& types) : dictionary_(dictionary), types_(types) {
    for (const auto& type : dictionary.data_types)
        if (!type.array_info.empty()) arrays_.emplace(&type, judge(type));
}

const ArraySize& DataTypeSizes::array(const DataType& type) const {
    static const ArraySize none;
    const auto it = arrays_.find(&type);
    return it == arrays_.end() ? none : it->second;
}

bool DataTypeSizes::used_as_soe_list(const DataType& type, std::uint64_t element_data_bits) {
    if (!users_built_) {
        users_built_ = true;
        for (const auto& t : dictionary_.data_types)
            for (const auto& item : t.sub_items)
                if (item.bit_size > 0) users_[trim(item.type)].push_back(Use{&item, &t, item.bit_size});
        for (const auto& object : dictionary_.objects)
            if (object.bit_size > 0) users_[trim(object.type)].push_back(Use{nullptr, nullptr, object.bit_size});
    }
    const auto it = users_.find(type.name);
    if (it == users_.end() || it->second.empty()) return false;
    for (const Use& use : it->second)
        if (!use.item || use.bit_size != element_data_bits || use.owner->bit_size != type.bit_size ||
            !has_list_header(*use.owner, *use.item))
            return false;
    return true;
}

ArraySize DataTypeSizes::judge(const DataType& type) {
    ArraySize out;
    out.elements = 1;
    for (const auto& info : type.array_info) {
        // Elements 0 with BitSize 0 is an empty list (Beckhoff's DT1C12ARR of a device without
        // RxPdos) and consistent; a negative count is not.
        if (info.elements < 0) {
            out.fit = ArrayFit::negative;
            out.negative = &info;
            return out;
        }
        out.elements *= static_cast<std::uint64_t>(info.elements);
    }
    if (type.bit_size == 0 || !type.base_type) return out;
    const std::optional<std::uint64_t> element_bits = types_.bit_size(*type.base_type);
    if (!element_bits || *element_bits == 0) return out;
    out.element_bits = *element_bits;
    const std::uint64_t data_bits = out.elements * out.element_bits;
    if (data_bits == type.bit_size) out.fit = ArrayFit::consistent;
    else if (out.element_bits < 8 && type.bit_size == (data_bits + 7) / 8 * 8) out.fit = ArrayFit::whole_bytes;
    else if (type.bit_size == data_bits + 32 && used_as_soe_list(type, data_bits)) out.fit = ArrayFit::soe_list;
    else out.fit = ArrayFit::mismatch;
    return out;
}

bool DataTypeSizes::own_size_accounts_for_users(const DataType& type) const {
    switch (array(type).fit) {
        case ArrayFit::soe_list:
        case ArrayFit::whole_bytes:
        case ArrayFit::mismatch: return true;
        default: break;
    }
    return layout_faults(type).past_end != nullptr;
}

}  // namespace esi::rules
