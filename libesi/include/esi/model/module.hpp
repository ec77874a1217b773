#pragma once
// Modules (pluggable units of a modular device) and the Slots of a device that take them.

#include "esi/model/dictionary.hpp"
#include "esi/model/mailbox.hpp"
#include "esi/model/pdo.hpp"

namespace esi {

struct Module {
    std::string type;  // Type text
    std::uint32_t module_ident = 0;
    SourcePos type_pos;
    std::optional<std::string> module_class;
    std::optional<std::int32_t> module_pdo_group;
    Extras type_extras;  // further Type attributes (SRA_ParameterSupported …)
    Names names;
    std::vector<Pdo> rx_pdos;
    std::vector<Pdo> tx_pdos;
    std::optional<Mailbox> mailbox;
    std::optional<Profile> profile;
    std::optional<std::string> dc_op_mode_name;
    Images images;
    SourcePos pos;
    Extras extras;  // SafetyParaMapping, VendorSpecific …
};

struct SlotModuleIdent {
    std::uint32_t value = 0;
    std::optional<std::uint32_t> default_ident;  // @Default
    SourcePos pos;
};

struct SlotModuleClass {
    std::string class_name;
    std::optional<std::uint32_t> vendor_id;
    Names names;
    SourcePos pos;
    Extras extras;
};

struct Slot {
    Names names;
    std::vector<SlotModuleIdent> module_idents;
    std::vector<SlotModuleClass> module_classes;
    std::optional<std::uint32_t> slot_group;
    std::uint32_t min_instances = 0;
    std::uint32_t max_instances = 0;
    std::optional<std::uint32_t> slot_pdo_increment;
    std::optional<std::uint32_t> slot_group_pdo_increment;
    std::optional<std::uint32_t> slot_index_increment;
    std::optional<std::uint32_t> slot_group_index_increment;
    std::optional<std::uint32_t> default_ident;  // @Default
    std::optional<std::uint32_t> fallback;
    Images images;
    SourcePos pos;
    Extras extras;
};

struct Slots {
    std::vector<Slot> slots;
    std::optional<std::uint32_t> max_slot_count;
    std::optional<std::uint32_t> max_slot_group_count;
    std::optional<std::uint32_t> slot_pdo_increment;
    std::optional<std::uint32_t> slot_group_pdo_increment;
    std::optional<std::uint32_t> slot_index_increment;
    std::optional<std::uint32_t> slot_group_index_increment;
    SourcePos pos;
    Extras extras;  // SlotGroupData, ModulePdoGroup, SlotSelections, download attributes
};

}  // namespace esi
