// ESI writer: Device (DeviceType of EtherCATInfo.xsd 1.17) with its identity, FMMUs,
// SyncManagers, sync units, PDOs, Dc, Slots and Eeprom; and Module (ModuleType of
// EtherCATBase.xsd), which shares PDOs and Mailbox (writer_mailbox.cpp) with Device.

#include "xml/writer_model.hpp"

namespace esi::xml_writer {

namespace {

constexpr std::string_view device_order[] = {
    "Sci",  "Type", "HideType", "AlternativeType", "SubDevice", "Name", "Comment", "URL",    "Info",
    "GroupType", "Profile", "Fmmu", "Sm", "Su", "RxPdo", "TxPdo", "Mailbox", "Dc", "Slots", "ESC", "Eeprom",
    "Image16x14", "ImageFile16x14", "ImageData16x14", "VendorSpecific"};
constexpr std::string_view pdo_order[] = {"Index", "Name", "Exclude", "Entry", "ExcludedSm"};
constexpr std::string_view entry_order[] = {"Index", "SubIndex", "BitLen", "Name", "Comment", "DataType"};
constexpr std::string_view dc_order[] = {"OpMode", "VendorSpecific"};
constexpr std::string_view op_mode_order[] = {"Name",           "Desc",           "AssignActivate", "CycleTimeSync0", "ShiftTimeSync0",
                                              "CycleTimeSync1", "ShiftTimeSync1", "Sm",             "VendorSpecific"};
constexpr std::string_view slots_order[] = {"Slot", "SlotGroupData", "ModulePdoGroup", "SlotSelections"};
constexpr std::string_view slot_order[] = {"Name", "ModuleIdent", "ModuleClass", "Image16x14", "ImageFile16x14", "ImageData16x14"};
constexpr std::string_view module_class_order[] = {"Class", "VendorId", "Name", "Image16x14", "ImageFile16x14", "ImageData16x14"};
constexpr std::string_view eeprom_order[] = {"Data", "ByteSize", "ConfigData", "BootStrap", "Category", "VendorSpecific"};
constexpr std::string_view category_order[] = {"CatNo", "Data", "DataString", "DataUINT", "DataUDINT"};
constexpr std::string_view module_order[] = {"Type",    "Name",         "RxPdo",      "TxPdo",          "SafetyParaMapping",
                                              "Mailbox", "Profile",      "DcOpModeName", "Image16x14", "ImageFile16x14",
                                              "ImageData16x14", "VendorSpecific"};

// An element with simple content and, possibly, unknown children kept by the reader.
void write_simple_content(XmlEmitter& out, std::string_view text, const Extras& extras) {
    out.text(text);
    ChildPlacer children(out, extras, no_children);
    children.finish();
}

void write_identity(XmlEmitter& out, const DeviceIdentity& type) {
    out.begin("Type");
    put_hex(out, "ProductCode", type.product_code, identity_hex);
    put_hex(out, "RevisionNo", type.revision_no, identity_hex);
    put_hex(out, "SerialNo", type.serial_no, identity_hex);
    put_bool(out, "TcCfgModeSafeOp", type.tc_cfg_mode_safe_op);
    write_extra_attributes(out, type.extras);
    write_simple_content(out, type.text, type.extras);
    out.end();
}

void write_fmmu(XmlEmitter& out, const Fmmu& fmmu) {
    out.begin("Fmmu");
    put_decimal(out, "Sm", fmmu.sm);
    put_decimal(out, "Su", fmmu.su);
    put_bool(out, "OpOnly", fmmu.op_only);
    write_extra_attributes(out, fmmu.extras);
    write_simple_content(out, fmmu.type, fmmu.extras);
    out.end();
}

void write_sm(XmlEmitter& out, const SyncManager& sm) {
    out.begin("Sm");
    // The order vendors and the ETG.2000 examples use, not the schema's declaration order.
    put_hex(out, "StartAddress", sm.start_address, index_hex);
    put_hex(out, "ControlByte", sm.control_byte, byte_hex);
    put_decimal(out, "DefaultSize", sm.default_size);
    put_decimal(out, "MinSize", sm.min_size);
    put_decimal(out, "MaxSize", sm.max_size);
    put_decimal(out, "Enable", sm.enable);
    put_bool(out, "OneByteMode", sm.one_byte_mode);
    put_bool(out, "Virtual", sm.is_virtual);
    put_bool(out, "Watchdog", sm.watchdog);
    put_bool(out, "OpOnly", sm.op_only);
    put_bool(out, "FixedAssignment", sm.fixed_assignment);
    write_extra_attributes(out, sm.extras);
    write_simple_content(out, sm.type, sm.extras);
    out.end();
}

void write_su(XmlEmitter& out, const SyncUnit& su) {
    out.begin("Su");
    put_bool(out, "SeparateSu", su.separate_su);
    put_bool(out, "SeparateFrame", su.separate_frame);
    put_bool(out, "DependOnInputState", su.depend_on_input_state);
    put_bool(out, "FrameRepeatSupport", su.frame_repeat_support);
    write_extra_attributes(out, su.extras);
    write_simple_content(out, su.text, su.extras);
    out.end();
}

void write_entry(XmlEmitter& out, const PdoEntry& entry) {
    out.begin("Entry");
    put_bool(out, "Fixed", entry.fixed);
    write_extra_attributes(out, entry.extras);
    ChildPlacer children(out, entry.extras, entry_order);
    children.at("Index");
    write_index(out, entry.index, entry.index_depend_on_slot, entry.index_depend_on_slot_group);
    if (entry.subindex) {
        children.at("SubIndex");
        leaf_decimal(out, "SubIndex", *entry.subindex);
    }
    children.at("BitLen");
    leaf_decimal(out, "BitLen", entry.bit_len);
    write_names(out, children, "Name", entry.names);
    if (entry.comment) {
        children.at("Comment");
        out.leaf("Comment", *entry.comment);
    }
    if (entry.data_type || entry.data_type_dscale || entry.data_type_swap_data) {
        children.at("DataType");
        out.begin("DataType");
        put_text(out, "DScale", entry.data_type_dscale);
        put_text(out, "SwapData", entry.data_type_swap_data);
        if (entry.data_type) out.text(*entry.data_type);
        out.end();
    }
    children.finish();
    out.end();
}

void write_pdo(XmlEmitter& out, const Pdo& pdo, std::string_view element) {
    out.begin(element);
    put_bool(out, "Fixed", pdo.fixed);
    put_bool(out, "Mandatory", pdo.mandatory);
    put_bool(out, "Virtual", pdo.is_virtual);
    put_decimal(out, "Sm", pdo.sm);
    put_decimal(out, "Su", pdo.su);
    put_decimal(out, "PdoOrder", pdo.pdo_order);
    put_decimal(out, "OSFac", pdo.os_fac);
    put_decimal(out, "OSMin", pdo.os_min);
    put_decimal(out, "OSMax", pdo.os_max);
    put_decimal(out, "OSIndexInc", pdo.os_index_inc);
    put_bool(out, "OverwrittenByModule", pdo.overwritten_by_module);
    put_bool(out, "SRA_Parameter", pdo.sra_parameter);
    put_text(out, "SafetyPdoType", pdo.safety_pdo_type);
    put_decimal(out, "SafetyConnNumber", pdo.safety_conn_number);
    write_extra_attributes(out, pdo.extras);
    ChildPlacer children(out, pdo.extras, pdo_order);
    children.at("Index");
    write_index(out, pdo.index, pdo.index_depend_on_slot, pdo.index_depend_on_slot_group);
    write_names(out, children, "Name", pdo.names);
    for (const auto& exclude : pdo.excludes) {
        children.at("Exclude");
        out.begin("Exclude");
        put_bool(out, "DependOnSlot", exclude.depend_on_slot);
        put_bool(out, "DependOnSlotGroup", exclude.depend_on_slot_group);
        out.text(index_hex(exclude.index).view());
        out.end();
    }
    for (const auto& entry : pdo.entries) {
        children.at("Entry");
        write_entry(out, entry);
    }
    for (const auto sm : pdo.excluded_sms) {
        children.at("ExcludedSm");
        leaf_decimal(out, "ExcludedSm", sm);
    }
    children.finish();
    out.end();
}

void write_dc_time(XmlEmitter& out, std::string_view element, const DcTime& time) {
    out.begin(element);
    put_decimal(out, "Factor", time.factor);
    put_bool(out, "Input", time.input);
    put_decimal(out, "OutputDelayTime", time.output_delay_time);
    put_decimal(out, "InputDelayTime", time.input_delay_time);
    out.text(NumberText::decimal(time.value).view());
    out.end();
}

void write_op_mode(XmlEmitter& out, const DcOpMode& mode) {
    out.begin("OpMode");
    write_extra_attributes(out, mode.extras);
    ChildPlacer children(out, mode.extras, op_mode_order);
    children.at("Name");
    out.leaf("Name", mode.name);
    if (mode.desc) {
        children.at("Desc");
        out.leaf("Desc", *mode.desc);
    }
    // has_assign_activate tells "AssignActivate 0" from "none"; a non-zero value in a hand-built
    // model is written even when the flag was not set.
    if (mode.has_assign_activate || mode.assign_activate != 0) {
        children.at("AssignActivate");
        out.leaf("AssignActivate", index_hex(mode.assign_activate).view());
    }
    const std::pair<std::string_view, const std::optional<DcTime>*> times[] = {
        {"CycleTimeSync0", &mode.cycle_time_sync0},
        {"ShiftTimeSync0", &mode.shift_time_sync0},
        {"CycleTimeSync1", &mode.cycle_time_sync1},
        {"ShiftTimeSync1", &mode.shift_time_sync1}};
    for (const auto& [element, time] : times) {
        if (!*time) continue;
        children.at(element);
        write_dc_time(out, element, **time);
    }
    children.finish();
    out.end();
}

void write_dc(XmlEmitter& out, const Dc& dc) {
    out.begin("Dc");
    put_bool(out, "UnknownFRMW", dc.unknown_frmw);
    put_bool(out, "Unknown64Bit", dc.unknown_64bit);
    put_bool(out, "ExternalRefClock", dc.external_ref_clock);
    put_bool(out, "PotentialReferenceClock", dc.potential_reference_clock);
    put_bool(out, "TimeLoopControlOnly", dc.time_loop_control_only);
    write_extra_attributes(out, dc.extras);
    ChildPlacer children(out, dc.extras, dc_order);
    for (const auto& mode : dc.op_modes) {
        children.at("OpMode");
        write_op_mode(out, mode);
    }
    children.finish();
    out.end();
}

void write_module_class(XmlEmitter& out, const SlotModuleClass& module_class) {
    out.begin("ModuleClass");
    write_extra_attributes(out, module_class.extras);
    ChildPlacer children(out, module_class.extras, module_class_order);
    children.at("Class");
    out.leaf("Class", module_class.class_name);
    if (module_class.vendor_id) {
        children.at("VendorId");
        out.leaf("VendorId", identity_hex(*module_class.vendor_id).view());
    }
    write_names(out, children, "Name", module_class.names);
    children.finish();
    out.end();
}

void write_slot(XmlEmitter& out, const Slot& slot) {
    out.begin("Slot");
    put_decimal(out, "SlotGroup", slot.slot_group);
    put_decimal(out, "MinInstances", slot.min_instances);
    put_decimal(out, "MaxInstances", slot.max_instances);
    put_decimal(out, "SlotPdoIncrement", slot.slot_pdo_increment);
    put_decimal(out, "SlotGroupPdoIncrement", slot.slot_group_pdo_increment);
    put_decimal(out, "SlotIndexIncrement", slot.slot_index_increment);
    put_decimal(out, "SlotGroupIndexIncrement", slot.slot_group_index_increment);
    put_hex(out, "Default", slot.default_ident, identity_hex);
    put_hex(out, "Fallback", slot.fallback, identity_hex);
    write_extra_attributes(out, slot.extras);
    ChildPlacer children(out, slot.extras, slot_order);
    write_names(out, children, "Name", slot.names);
    for (const auto& ident : slot.module_idents) {
        children.at("ModuleIdent");
        out.begin("ModuleIdent");
        // Default marks the slot's default module (vendors write 0/1); kept decimal.
        put_decimal(out, "Default", ident.default_ident);
        out.text(identity_hex(ident.value).view());
        out.end();
    }
    for (const auto& module_class : slot.module_classes) {
        children.at("ModuleClass");
        write_module_class(out, module_class);
    }
    write_images(out, children, slot.images);
    children.finish();
    out.end();
}

void write_slots(XmlEmitter& out, const Slots& slots) {
    out.begin("Slots");
    put_decimal(out, "MaxSlotCount", slots.max_slot_count);
    put_decimal(out, "MaxSlotGroupCount", slots.max_slot_group_count);
    put_decimal(out, "SlotPdoIncrement", slots.slot_pdo_increment);
    put_decimal(out, "SlotGroupPdoIncrement", slots.slot_group_pdo_increment);
    put_decimal(out, "SlotIndexIncrement", slots.slot_index_increment);
    put_decimal(out, "SlotGroupIndexIncrement", slots.slot_group_index_increment);
    write_extra_attributes(out, slots.extras);
    ChildPlacer children(out, slots.extras, slots_order);
    for (const auto& slot : slots.slots) {
        children.at("Slot");
        write_slot(out, slot);
    }
    children.finish();
    out.end();
}

void write_category(XmlEmitter& out, const EepromCategory& category) {
    out.begin("Category");
    put_bool(out, "PreserveOnlineData", category.preserve_online_data);
    write_extra_attributes(out, category.extras);
    ChildPlacer children(out, category.extras, category_order);
    children.at("CatNo");
    leaf_decimal(out, "CatNo", category.cat_no);
    if (category.data) {
        children.at("Data");
        leaf_hex_data(out, "Data", *category.data);
    }
    if (category.data_string) {
        children.at("DataString");
        out.leaf("DataString", *category.data_string);
    }
    if (category.data_uint) {
        children.at("DataUINT");
        leaf_decimal(out, "DataUINT", *category.data_uint);
    }
    if (category.data_udint) {
        children.at("DataUDINT");
        leaf_decimal(out, "DataUDINT", *category.data_udint);
    }
    children.finish();
    out.end();
}

void write_eeprom(XmlEmitter& out, const Eeprom& eeprom) {
    out.begin("Eeprom");
    put_bool(out, "AssignToPdi", eeprom.assign_to_pdi);
    write_extra_attributes(out, eeprom.extras);
    ChildPlacer children(out, eeprom.extras, eeprom_order);
    if (eeprom.data) {
        children.at("Data");
        leaf_hex_data(out, "Data", *eeprom.data);
    }
    if (eeprom.byte_size) {
        children.at("ByteSize");
        leaf_decimal(out, "ByteSize", *eeprom.byte_size);
    }
    if (eeprom.config_data) {
        children.at("ConfigData");
        leaf_hex_data(out, "ConfigData", *eeprom.config_data);
    }
    if (eeprom.boot_strap) {
        children.at("BootStrap");
        leaf_hex_data(out, "BootStrap", *eeprom.boot_strap);
    }
    for (const auto& category : eeprom.categories) {
        children.at("Category");
        write_category(out, category);
    }
    children.finish();
    out.end();
}

void write_pdos(XmlEmitter& out, ChildPlacer& children, const std::vector<Pdo>& pdos, std::string_view element) {
    for (const auto& pdo : pdos) {
        children.at(element);
        write_pdo(out, pdo, element);
    }
}

}  // namespace

void write_device(XmlEmitter& out, const Device& device) {
    out.begin("Device");
    out.attribute("Physics", device.physics);  // required by the schema
    put_bool(out, "Invisible", device.invisible);
    write_extra_attributes(out, device.extras);
    ChildPlacer children(out, device.extras, device_order);
    children.at("Type");
    write_identity(out, device.type);
    write_names(out, children, "Name", device.names);
    write_names(out, children, "Comment", device.comments);
    write_names(out, children, "URL", device.urls);
    if (device.group_type) {
        children.at("GroupType");
        out.leaf("GroupType", *device.group_type);
    }
    for (const auto& profile : device.profiles) {
        children.at("Profile");
        write_profile(out, profile);
    }
    for (const auto& fmmu : device.fmmus) {
        children.at("Fmmu");
        write_fmmu(out, fmmu);
    }
    for (const auto& sm : device.sms) {
        children.at("Sm");
        write_sm(out, sm);
    }
    for (const auto& su : device.sus) {
        children.at("Su");
        write_su(out, su);
    }
    write_pdos(out, children, device.rx_pdos, "RxPdo");
    write_pdos(out, children, device.tx_pdos, "TxPdo");
    if (device.mailbox) {
        children.at("Mailbox");
        write_mailbox(out, *device.mailbox);
    }
    if (device.dc) {
        children.at("Dc");
        write_dc(out, *device.dc);
    }
    if (device.slots) {
        children.at("Slots");
        write_slots(out, *device.slots);
    }
    if (device.eeprom) {
        children.at("Eeprom");
        write_eeprom(out, *device.eeprom);
    }
    write_images(out, children, device.images);
    children.finish();
    out.end();
}

void write_module(XmlEmitter& out, const Module& module) {
    out.begin("Module");
    write_extra_attributes(out, module.extras);
    ChildPlacer children(out, module.extras, module_order);
    children.at("Type");
    out.begin("Type");
    out.attribute("ModuleIdent", identity_hex(module.module_ident).view());  // required by the schema
    put_text(out, "ModuleClass", module.module_class);
    put_decimal(out, "ModulePdoGroup", module.module_pdo_group);
    write_extra_attributes(out, module.type_extras);
    out.text(module.type);
    out.end();
    write_names(out, children, "Name", module.names);
    write_pdos(out, children, module.rx_pdos, "RxPdo");
    write_pdos(out, children, module.tx_pdos, "TxPdo");
    if (module.mailbox) {
        children.at("Mailbox");
        write_mailbox(out, *module.mailbox);
    }
    if (module.profile) {
        children.at("Profile");
        write_profile(out, *module.profile);
    }
    if (module.dc_op_mode_name) {
        children.at("DcOpModeName");
        out.leaf("DcOpModeName", *module.dc_op_mode_name);
    }
    write_images(out, children, module.images);
    children.finish();
    out.end();
}

}  // namespace esi::xml_writer
