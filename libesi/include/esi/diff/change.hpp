#pragma once
// One difference between two ESI files, as esi-diff reports it: where it is (device, model path,
// positions in both files), what kind of change it is, and how a master configured from the old
// file is affected (its class). The kinds and their classes are listed in classification.hpp.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "esi/source_pos.hpp"

namespace esi {

// Ordered by severity: a higher value is worse.
enum class ChangeClass {
    cosmetic,    // names, descriptions, comments, images, unmodelled XML: nothing a master uses
    compatible,  // additions a master configured from the old file may ignore
    breaking,    // a master configured from the old file can fail or misread data
};

// The overall result of a comparison: the most severe class found, or identical.
enum class Verdict { identical, cosmetic, compatible, breaking };

[[nodiscard]] std::string_view to_string(ChangeClass change_class);
[[nodiscard]] std::string_view to_string(Verdict verdict);
[[nodiscard]] Verdict verdict_of(ChangeClass change_class);

// Every kind of change the differ reports. The id (kebab-case), class and reason of each are
// in the one table of classification.cpp.
enum class ChangeKind {
    // the file as a whole
    document_kind_changed,
    info_version_changed,
    vendor_id_changed,
    vendor_changed,
    group_added,
    group_removed,
    group_changed,
    module_added,
    module_removed,
    module_attribute_changed,
    // device identity and description
    device_added,
    device_removed,
    device_revision_added,
    revision_changed,
    revision_not_changed,  // the error: breaking changes under an unchanged RevisionNo
    type_text_changed,
    name_changed,
    comment_changed,
    image_changed,
    group_type_changed,
    physics_changed,
    physics_ports_added,
    device_flag_changed,
    profile_number_changed,
    profile_changed,
    // SyncManagers, FMMUs, sync units
    sm_added,
    sm_removed,
    sm_type_declared,
    sm_type_changed,
    sm_address_changed,
    sm_control_byte_changed,
    sm_size_changed,
    sm_size_limits_widened,
    sm_size_limits_narrowed,
    sm_enable_changed,
    sm_flag_changed,
    fmmu_added,
    fmmu_removed,
    fmmu_changed,
    sync_unit_added,
    sync_unit_removed,
    sync_unit_changed,
    // PDOs and their entries
    pdo_added,
    pdo_added_assigned,
    pdo_removed,
    pdo_sm_changed,
    sm_assignment_order_changed,
    pdo_fixed_set,
    pdo_fixed_cleared,
    pdo_mandatory_set,
    pdo_mandatory_cleared,
    pdo_exclude_added,
    pdo_exclude_removed,
    pdo_attribute_changed,
    pdo_entry_added,
    pdo_entry_removed,
    pdo_entry_moved,
    pdo_entry_index_changed,
    pdo_entry_bit_len_changed,
    pdo_entry_data_type_changed,
    pdo_entry_data_type_declared,
    pdo_entry_attribute_changed,
    // object dictionary
    object_added,
    object_removed,
    object_code_changed,
    object_size_changed,
    object_entry_added,
    object_entry_removed,
    object_entry_type_changed,
    object_entry_offset_changed,
    object_access_narrowed,
    object_access_widened,
    object_pdo_mapping_removed,
    object_pdo_mapping_added,
    object_default_changed,
    pdo_mapping_default_changed,
    object_limits_narrowed,
    object_limits_widened,
    object_limits_changed,
    object_flags_changed,
    data_type_added,
    data_type_removed,
    data_type_changed,
    data_type_text_changed,
    // mailbox and InitCmds
    mailbox_added,
    mailbox_removed,
    mailbox_protocol_added,
    mailbox_protocol_removed,
    mailbox_flag_set,
    mailbox_flag_cleared,
    mailbox_channels_changed,
    mailbox_attribute_changed,
    init_cmd_added,
    init_cmd_removed,
    init_cmd_changed,
    init_cmd_order_changed,
    // distributed clocks
    dc_op_mode_added,
    dc_op_mode_removed,
    dc_assign_activate_changed,
    dc_timing_changed,
    dc_attribute_changed,
    // EEPROM
    eeprom_added,
    eeprom_removed,
    eeprom_size_increased,
    eeprom_size_decreased,
    eeprom_config_data_changed,
    eeprom_boot_strap_changed,
    eeprom_data_changed,
    eeprom_category_added,
    eeprom_category_removed,
    eeprom_category_changed,
    eeprom_attribute_changed,
    // modular devices
    slot_added,
    slot_removed,
    slot_module_added,
    slot_module_removed,
    slot_instances_widened,
    slot_instances_narrowed,
    slot_layout_changed,
    slot_default_changed,
    // anything else
    extras_changed,
    spelling_changed,
};

// The device a change belongs to. For a device that is a new revision of one in the old file,
// `revision` is the new revision and `compared_revision` the old one it was compared with.
struct DeviceRef {
    std::string name;  // the English (else first) Name, else the Type text
    std::string type;  // the Type text (order code)
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision;
    std::optional<std::uint32_t> compared_revision;

    friend bool operator==(const DeviceRef&, const DeviceRef&) = default;
};

struct Change {
    std::optional<DeviceRef> device;  // absent for changes of the file as a whole (vendor, groups, modules)
    std::string path;                 // model path within the device (or the file), e.g. "RxPdo[#x1600]/Entry[#x7000:01]/BitLen"
    ChangeKind kind = ChangeKind::extras_changed;
    ChangeClass change_class = ChangeClass::cosmetic;
    std::optional<std::string> old_value;  // absent when the element is added
    std::optional<std::string> new_value;  // absent when the element is removed
    // Positions of the element in each file; for an element on one side only, the other side's
    // position is that of the nearest enclosing element that exists there.
    SourcePos old_pos;
    SourcePos new_pos;
    std::string message;
};

}  // namespace esi
