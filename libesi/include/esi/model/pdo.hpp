#pragma once
// RxPdo / TxPdo (PdoType) of a device or module.

#include "esi/model/common.hpp"

namespace esi {

enum class PdoDirection { rx, tx };  // rx: master -> slave (outputs); tx: slave -> master (inputs)

struct PdoEntry {
    std::uint32_t index = 0;  // 0 = padding
    SourcePos index_pos;      // the Index element; line 0 when it is missing
    bool index_invalid = false;  // Index present but not a number (reported by the reader); index is then 0
    std::optional<bool> index_depend_on_slot;
    std::optional<bool> index_depend_on_slot_group;
    std::optional<std::uint32_t> subindex;  // absent means 0
    std::uint32_t bit_len = 0;
    Names names;
    std::optional<std::string> comment;
    std::optional<std::string> data_type;  // as written (trimmed)
    std::optional<std::string> data_type_dscale;
    std::optional<std::string> data_type_swap_data;  // Swap_HB_LB, Swap_HW_LW, Swap_HB_LB_HW_LW
    std::optional<bool> fixed;
    SourcePos pos;
    SourcePos bit_len_pos;
    SourcePos data_type_pos;
    Extras extras;

    [[nodiscard]] bool is_padding() const { return index == 0 && !index_invalid; }
    [[nodiscard]] std::uint32_t effective_subindex() const { return subindex.value_or(0); }
};

struct PdoExclude {
    std::uint32_t index = 0;
    std::optional<bool> depend_on_slot;
    std::optional<bool> depend_on_slot_group;
    SourcePos pos;
};

struct Pdo {
    PdoDirection direction = PdoDirection::rx;
    std::uint32_t index = 0;  // 0x1600.. / 0x1A00..
    bool index_invalid = false;  // Index present but not a number (reported by the reader); index is then 0
    std::optional<bool> index_depend_on_slot;
    std::optional<bool> index_depend_on_slot_group;
    SourcePos index_pos;
    Names names;
    std::vector<PdoExclude> excludes;
    std::vector<PdoEntry> entries;
    std::vector<std::uint32_t> excluded_sms;
    std::optional<bool> fixed;
    std::optional<bool> mandatory;
    std::optional<bool> is_virtual;
    std::optional<std::uint32_t> sm;  // present: assigned to this SM by default
    std::optional<std::uint32_t> su;
    std::optional<std::int32_t> pdo_order;
    std::optional<std::int32_t> os_fac;
    std::optional<std::int32_t> os_min;
    std::optional<std::int32_t> os_max;
    std::optional<std::int32_t> os_index_inc;
    std::optional<bool> overwritten_by_module;
    std::optional<bool> sra_parameter;
    std::optional<std::string> safety_pdo_type;
    std::optional<std::int32_t> safety_conn_number;
    SourcePos pos;
    Extras extras;

    // Sum of the entries' BitLen.
    [[nodiscard]] std::uint64_t bit_size() const;
    [[nodiscard]] std::string_view element_name() const { return direction == PdoDirection::rx ? "RxPdo" : "TxPdo"; }
};

}  // namespace esi
