// The classification table of esi-diff. The question each row answers: can a master configured
// from the OLD file fail or misread data with a device described by the NEW file? (breaking);
// is it something new it may ignore? (compatible); or does nothing a master uses change?
// (cosmetic). Facts cited: ETG.2000 (ESI specification), ETG.1000.6 (CoE), ETG.2010 (SII),
// ETG.2001 (modular devices), ETG.7000 CTT checks.

#include "esi/diff/classification.hpp"

#include <array>
#include <cstddef>

namespace esi {

namespace {

using K = ChangeKind;
using C = ChangeClass;

constexpr ChangeKindInfo table[] = {
    // ---- the file as a whole -------------------------------------------------------------
    {K::document_kind_changed, "document-kind-changed", C::cosmetic,
     "the root element differs (e.g. EtherCATInfo vs EtherCATInfoList); the devices inside are compared whatever holds them"},
    {K::info_version_changed, "info-version-changed", C::cosmetic,
     "EtherCATInfo@Version names the schema the file was written against; masters do not configure anything from it"},
    {K::vendor_id_changed, "vendor-id-changed", C::breaking,
     "masters identify a device by vendor Id, product code and revision (ETG.2000 Vendor/Id, SII words 0x08-0x09): a "
     "configuration made from the old file finds no device with the Id it expects"},
    {K::vendor_changed, "vendor-changed", C::cosmetic,
     "vendor file version, description URL and unique name are catalogue information"},
    {K::group_added, "group-added", C::cosmetic, "Groups only arrange devices in a configuration tool's catalogue tree"},
    {K::group_removed, "group-removed", C::cosmetic, "Groups only arrange devices in a configuration tool's catalogue tree"},
    {K::group_changed, "group-changed", C::cosmetic, "Groups only arrange devices in a configuration tool's catalogue tree"},
    {K::module_added, "module-added", C::compatible, "a new module a configuration from the old file does not use"},
    {K::module_removed, "module-removed", C::breaking,
     "a configuration that plugs this module into a slot cannot be built from the new file (ETG.2001)"},
    {K::module_attribute_changed, "module-attribute-changed", C::breaking,
     "ModuleClass, ModulePdoGroup and DcOpModeName decide which slots take the module and how its PDOs and DC mode are set up "
     "(ETG.2001)"},

    // ---- device identity and description ---------------------------------------------------
    {K::device_added, "device-added", C::compatible, "a new product a configuration from the old file does not use"},
    {K::device_removed, "device-removed", C::breaking,
     "a configuration that uses this device cannot be rebuilt or checked against the new file"},
    {K::device_revision_added, "device-revision-added", C::compatible,
     "a new revision next to one the new file still describes: configurations from the old file keep their revision"},
    {K::revision_changed, "revision-changed", C::compatible,
     "the RevisionNo is how a device announces that it changed; masters compare it with the device's SII and report a mismatch "
     "instead of misreading data. What differs between the revisions is reported change by change"},
    {K::revision_not_changed, "revision-not-changed", C::breaking,
     "masters match devices by vendor, product code and revision (ETG.2000 Device/Type, CTT 2-1..2-3): breaking changes under "
     "the same RevisionNo reach configured plants unnoticed"},
    {K::type_text_changed, "type-text-changed", C::cosmetic,
     "the Type text is the order code shown to users; masters match ProductCode and RevisionNo"},
    {K::name_changed, "name-changed", C::cosmetic, "names (per LcId) are shown to users only"},
    {K::comment_changed, "comment-changed", C::cosmetic,
     "comments, URLs, descriptions and display names are shown to users only"},
    {K::image_changed, "image-changed", C::cosmetic, "icons are shown to users only"},
    {K::group_type_changed, "group-type-changed", C::cosmetic, "GroupType only places the device in the catalogue tree"},
    {K::physics_changed, "physics-changed", C::breaking,
     "Physics gives the port types (MII, E-Bus); masters check the topology against it (CTT 1-3: ESI port type vs SII)"},
    {K::physics_ports_added, "physics-ports-added", C::compatible,
     "Physics lists more ports while the existing ones keep their type; a topology configured from the old file leaves them "
     "unconnected"},
    {K::device_flag_changed, "device-flag-changed", C::cosmetic,
     "Invisible, SerialNo and TcCfgModeSafeOp (deprecated, CTT 5-5) only steer how a tool lists the device"},
    {K::profile_number_changed, "profile-number-changed", C::breaking,
     "ProfileNo tells a master which object semantics to apply (e.g. 402 drive, 5001 modular device); a configuration made for "
     "the old profile no longer fits"},
    {K::profile_changed, "profile-changed", C::compatible,
     "AddInfo, Channel (deprecated) and DictionaryFile describe the profile further without changing the objects a master uses"},

    // ---- SyncManagers, FMMUs, sync units ----------------------------------------------------
    {K::sm_added, "sm-added", C::breaking,
     "the SyncManager layout changes; masters write every SyncManager the description lists into the ESC (ETG.2000 Sm)"},
    {K::sm_removed, "sm-removed", C::breaking,
     "the SyncManager layout changes; a master configured from the old file sets up a SyncManager the device no longer has"},
    {K::sm_type_declared, "sm-type-declared", C::compatible,
     "a SyncManager that had no type text now declares one; start address, control byte and size stay as they were"},
    {K::sm_type_changed, "sm-type-changed", C::breaking,
     "the SyncManager now serves another purpose (mailbox out/in, outputs, inputs)"},
    {K::sm_address_changed, "sm-address-changed", C::breaking,
     "the master writes StartAddress into the SyncManager registers (0x0800+); data would go to the wrong ESC memory"},
    {K::sm_control_byte_changed, "sm-control-byte-changed", C::breaking,
     "ControlByte sets direction and buffer/mailbox mode of the SyncManager"},
    {K::sm_size_changed, "sm-size-changed", C::breaking,
     "the SyncManager length is the mailbox size or the process-image size of that direction"},
    {K::sm_size_limits_widened, "sm-size-limits-widened", C::compatible,
     "every size allowed before is still allowed (MinSize/MaxSize)"},
    {K::sm_size_limits_narrowed, "sm-size-limits-narrowed", C::breaking,
     "a SyncManager size valid for the old file may now be out of range (MinSize/MaxSize)"},
    {K::sm_enable_changed, "sm-enable-changed", C::breaking, "Enable is written into the SyncManager activation register"},
    {K::sm_flag_changed, "sm-flag-changed", C::breaking,
     "Virtual, Watchdog, OpOnly, FixedAssignment and OneByteMode change how the master sets up the SyncManager"},
    {K::fmmu_added, "fmmu-added", C::compatible, "an extra FMMU (e.g. MBoxState) a master may leave unused"},
    {K::fmmu_removed, "fmmu-removed", C::breaking,
     "a master configured from the old file maps data through an FMMU the device no longer offers"},
    {K::fmmu_changed, "fmmu-changed", C::breaking, "the FMMU now maps another kind of data or another SyncManager"},
    {K::sync_unit_added, "sync-unit-added", C::compatible, "a new sync unit a configuration from the old file does not use"},
    {K::sync_unit_removed, "sync-unit-removed", C::breaking, "PDOs configured into this sync unit have nowhere to go"},
    {K::sync_unit_changed, "sync-unit-changed", C::breaking,
     "the sync unit is exchanged in another frame or under other conditions"},

    // ---- PDOs and their entries -------------------------------------------------------------
    {K::pdo_added, "pdo-added", C::compatible, "a new optional PDO (not assigned by default) a master may ignore"},
    {K::pdo_added_assigned, "pdo-added-assigned", C::breaking,
     "the new PDO is assigned to a SyncManager by default (Sm attribute), so the default process image grows"},
    {K::pdo_removed, "pdo-removed", C::breaking,
     "a master configured from the old file assigns or maps a PDO the device no longer has"},
    {K::pdo_sm_changed, "pdo-sm-changed", C::breaking,
     "the default SyncManager assignment of the PDO changes, and with it the default process image"},
    {K::sm_assignment_order_changed, "sm-assignment-order-changed", C::breaking,
     "the order of the PDOs assigned to a SyncManager is the order of their data in the process image (0x1C12/0x1C13)"},
    {K::pdo_fixed_set, "pdo-fixed-set", C::breaking,
     "the PDO mapping can no longer be changed; a configuration that changed it is rejected"},
    {K::pdo_fixed_cleared, "pdo-fixed-cleared", C::compatible,
     "the PDO mapping may now be changed; the old default is still valid"},
    {K::pdo_mandatory_set, "pdo-mandatory-set", C::breaking, "a configuration without this PDO is no longer valid"},
    {K::pdo_mandatory_cleared, "pdo-mandatory-cleared", C::compatible,
     "the PDO may now be left out; configurations that include it stay valid"},
    {K::pdo_exclude_added, "pdo-exclude-added", C::breaking,
     "a combination of PDOs (or SyncManagers) allowed before is now excluded"},
    {K::pdo_exclude_removed, "pdo-exclude-removed", C::compatible, "more PDO combinations are allowed; the old ones stay valid"},
    {K::pdo_attribute_changed, "pdo-attribute-changed", C::breaking,
     "Su, PdoOrder, oversampling (OSFac/OSMin/OSMax/OSIndexInc), Virtual, slot dependence and safety attributes change how the "
     "master builds the process image"},
    {K::pdo_entry_added, "pdo-entry-added", C::breaking, "the PDO grows: the offsets and the size of the process image change"},
    {K::pdo_entry_removed, "pdo-entry-removed", C::breaking,
     "the PDO shrinks: the offsets and the size of the process image change"},
    {K::pdo_entry_moved, "pdo-entry-moved", C::breaking,
     "the order of entries is the process-image layout; data would be read at the wrong offset"},
    {K::pdo_entry_index_changed, "pdo-entry-index-changed", C::breaking,
     "another object is mapped at this place of the process image"},
    {K::pdo_entry_bit_len_changed, "pdo-entry-bit-len-changed", C::breaking,
     "the entry's size changes, and with it the offsets of everything after it"},
    {K::pdo_entry_data_type_changed, "pdo-entry-data-type-changed", C::breaking,
     "the same bits are now interpreted as another type"},
    {K::pdo_entry_data_type_declared, "pdo-entry-data-type-declared", C::compatible,
     "a DataType is given or dropped while BitLen stays; the layout is unchanged"},
    {K::pdo_entry_attribute_changed, "pdo-entry-attribute-changed", C::breaking,
     "DScale, SwapData, Fixed and slot dependence change how the entry's value is scaled, ordered or indexed"},

    // ---- object dictionary ------------------------------------------------------------------
    {K::object_added, "object-added", C::compatible, "a new object a master configured from the old file does not access"},
    {K::object_removed, "object-removed", C::breaking, "SDO access or mapping of this object fails (abort 0x06020000)"},
    {K::object_code_changed, "object-code-changed", C::breaking,
     "the object changes between VAR, ARRAY and RECORD; sub-index access and CompleteAccess see another layout"},
    {K::object_size_changed, "object-size-changed", C::breaking,
     "the object's BitSize changes; an SDO transfer of the old length is rejected (abort 0x06070010)"},
    {K::object_entry_added, "object-entry-added", C::compatible,
     "a new sub-index a master configured from the old file does not access"},
    {K::object_entry_removed, "object-entry-removed", C::breaking, "SDO access to this sub-index fails (abort 0x06090011)"},
    {K::object_entry_type_changed, "object-entry-type-changed", C::breaking,
     "the sub-entry's type or size changes; values written or mapped for the old type are misread"},
    {K::object_entry_offset_changed, "object-entry-offset-changed", C::breaking,
     "the sub-entry moves within the object (BitOffs); CompleteAccess transfers see another layout"},
    {K::object_access_narrowed, "object-access-narrowed", C::breaking,
     "reading or writing allowed before (Access, Read/WriteRestrictions) is now refused"},
    {K::object_access_widened, "object-access-widened", C::compatible, "everything allowed before is still allowed"},
    {K::object_pdo_mapping_removed, "object-pdo-mapping-removed", C::breaking,
     "a PDO configuration that maps this entry is rejected (PdoMapping/SafetyMapping)"},
    {K::object_pdo_mapping_added, "object-pdo-mapping-added", C::compatible,
     "the entry may now also be mapped; old mappings stay valid"},
    {K::object_default_changed, "object-default-changed", C::compatible,
     "the initial value differs; SDO access and the process image are unchanged (a master that needs a value writes it by "
     "InitCmd)"},
    {K::pdo_mapping_default_changed, "pdo-mapping-default-changed", C::breaking,
     "the defaults of the mapping (0x1600-0x17FF, 0x1A00-0x1BFF) and assignment (0x1C10-0x1C2F) objects are the default process "
     "image (ETG.1000.6)"},
    {K::object_limits_narrowed, "object-limits-narrowed", C::breaking,
     "a value valid for the old file may now be refused (abort 0x06090030)"},
    {K::object_limits_widened, "object-limits-widened", C::compatible, "every value allowed before is still allowed"},
    {K::object_limits_changed, "object-limits-changed", C::breaking,
     "the allowed range changed in a way that cannot be ordered (limits given as data); values valid before may be refused"},
    {K::object_flags_changed, "object-flags-changed", C::compatible,
     "Category, Transition, SdoAccess, Backup, Setting and Attribute describe the object without changing how it is accessed or "
     "mapped"},
    {K::data_type_added, "data-type-added", C::compatible, "a new DataType; objects that use it are reported on their own"},
    {K::data_type_removed, "data-type-removed", C::compatible,
     "DataTypes are the vocabulary of the objects; an object whose layout changes because of it is reported on its own (as "
     "breaking)"},
    {K::data_type_changed, "data-type-changed", C::compatible,
     "DataTypes are the vocabulary of the objects; every object whose layout changes because of it is reported on its own (as "
     "breaking)"},
    {K::data_type_text_changed, "data-type-text-changed", C::cosmetic, "comments, display names and enum texts of a DataType"},

    // ---- mailbox and InitCmds ---------------------------------------------------------------
    {K::mailbox_added, "mailbox-added", C::compatible,
     "the device now offers a mailbox a configuration from the old file does not use"},
    {K::mailbox_removed, "mailbox-removed", C::breaking, "SDO, FoE, EoE … transfers configured from the old file fail"},
    {K::mailbox_protocol_added, "mailbox-protocol-added", C::compatible, "a new mailbox protocol a master may ignore"},
    {K::mailbox_protocol_removed, "mailbox-protocol-removed", C::breaking,
     "the device no longer announces the protocol (SII word 0x1C, CTT 2-5); transfers configured with it fail"},
    {K::mailbox_flag_set, "mailbox-flag-set", C::compatible,
     "the device announces an additional capability (e.g. CoE SdoInfo, CompleteAccess, EoE IP)"},
    {K::mailbox_flag_cleared, "mailbox-flag-cleared", C::breaking,
     "a capability announced before (e.g. CoE PdoAssign, CompleteAccess, DataLinkLayer) is gone; a master that uses it fails"},
    {K::mailbox_channels_changed, "mailbox-channels-changed", C::breaking,
     "the number of drive channels (CoE DS402Channels, SoE ChannelCount) decides how many axes a master sets up"},
    {K::mailbox_attribute_changed, "mailbox-attribute-changed", C::compatible,
     "EdsFile describes the mailbox further, and PdoUpload (SII General CoE details bit 4, upload at start-up) asks the master "
     "to read the PDO configuration; neither changes what a configuration relies on"},
    {K::init_cmd_added, "init-cmd-added", C::breaking,
     "the device now needs this command on a state transition; a master configured from the old file never sends it"},
    {K::init_cmd_removed, "init-cmd-removed", C::breaking,
     "a master configured from the old file still sends a command the new description dropped (e.g. to an object that no longer "
     "exists)"},
    {K::init_cmd_changed, "init-cmd-changed", C::breaking,
     "another value, target, transition or access mode is sent at start-up than the old file configured"},
    {K::init_cmd_order_changed, "init-cmd-order-changed", C::breaking,
     "InitCmds are sent in the order written; e.g. 0x1C12:00 must be cleared before the assignment is written (ETG.1000.6)"},

    // ---- distributed clocks -----------------------------------------------------------------
    {K::dc_op_mode_added, "dc-op-mode-added", C::compatible,
     "a new synchronisation mode a configuration from the old file does not select"},
    {K::dc_op_mode_removed, "dc-op-mode-removed", C::breaking,
     "a configuration that selected this DC mode cannot be rebuilt; the device may not support it any more"},
    {K::dc_assign_activate_changed, "dc-assign-activate-changed", C::breaking,
     "AssignActivate is written into the ESC's DC activation registers (0x0980); the device is synchronised differently"},
    {K::dc_timing_changed, "dc-timing-changed", C::breaking,
     "default Sync0/Sync1 cycle and shift times (and factors) change the timing the device expects"},
    {K::dc_attribute_changed, "dc-attribute-changed", C::breaking,
     "UnknownFRMW, Unknown64Bit, ExternalRefClock, PotentialReferenceClock and TimeLoopControlOnly tell a master how to run the "
     "clock through this device"},

    // ---- EEPROM -----------------------------------------------------------------------------
    {K::eeprom_added, "eeprom-added", C::compatible, "the file now describes the SII contents; a tool may program it"},
    {K::eeprom_removed, "eeprom-removed", C::breaking,
     "a tool that programs the SII from the file has nothing to write any more"},
    {K::eeprom_size_increased, "eeprom-size-increased", C::compatible, "an SII image made for the old size still fits"},
    {K::eeprom_size_decreased, "eeprom-size-decreased", C::breaking, "an SII image made for the old size may not fit (CTT 2-6)"},
    {K::eeprom_config_data_changed, "eeprom-config-data-changed", C::breaking,
     "ConfigData becomes the ESC's PDI and sync configuration at power-up (SII words 0-6, CTT 2-8); an old image written to a "
     "new device can leave its PDI dead"},
    {K::eeprom_boot_strap_changed, "eeprom-boot-strap-changed", C::breaking,
     "BootStrap gives the bootstrap mailbox offsets and sizes (SII words 0x14-0x17); mailbox sizes are layout"},
    {K::eeprom_data_changed, "eeprom-data-changed", C::breaking, "the complete SII image (Eeprom/Data) differs"},
    {K::eeprom_category_added, "eeprom-category-added", C::compatible, "an additional SII category a master may ignore"},
    {K::eeprom_category_removed, "eeprom-category-removed", C::breaking, "an SII category the old image carried is gone"},
    {K::eeprom_category_changed, "eeprom-category-changed", C::breaking, "the contents of an SII category differ"},
    {K::eeprom_attribute_changed, "eeprom-attribute-changed", C::breaking,
     "AssignToPdi and PreserveOnlineData decide who owns the EEPROM and what survives a rewrite"},

    // ---- modular devices --------------------------------------------------------------------
    {K::slot_added, "slot-added", C::compatible, "a new slot at the end; a configuration from the old file leaves it empty"},
    {K::slot_removed, "slot-removed", C::breaking,
     "a configuration that plugs a module into this slot cannot be built (ETG.2001)"},
    {K::slot_module_added, "slot-module-added", C::compatible, "the slot accepts one more module (ident or class)"},
    {K::slot_module_removed, "slot-module-removed", C::breaking,
     "a module plugged into this slot by a configuration from the old file is no longer accepted"},
    {K::slot_instances_widened, "slot-instances-widened", C::compatible, "every slot count allowed before is still allowed"},
    {K::slot_instances_narrowed, "slot-instances-narrowed", C::breaking,
     "a slot configuration valid before may have too few or too many instances"},
    {K::slot_layout_changed, "slot-layout-changed", C::breaking,
     "slot and slot-group increments and the SlotGroup shift the PDO and object indices of the plugged modules (ETG.2001)"},
    {K::slot_default_changed, "slot-default-changed", C::compatible,
     "the module proposed by default (Default, Fallback) differs; configured modules stay valid"},

    // ---- anything else ----------------------------------------------------------------------
    {K::extras_changed, "extras-changed", C::cosmetic,
     "XML the model does not cover (Info, ESC, vendor-specific elements …) is kept verbatim and compared, but no master "
     "configuration is derived from it here"},
    {K::spelling_changed, "spelling-changed", C::cosmetic,
     "the same thing written differently: a type alias (UINT16 for UINT), a renamed DataType with the same layout, letter case"},
};

constexpr std::size_t kind_count = static_cast<std::size_t>(ChangeKind::spelling_changed) + 1;
static_assert(std::size(table) == kind_count, "every ChangeKind needs exactly one row");

// The rows must follow the enum order so that a kind is its own row index.
constexpr bool rows_in_enum_order() {
    for (std::size_t i = 0; i < std::size(table); ++i)
        if (static_cast<std::size_t>(table[i].kind) != i) return false;
    return true;
}
static_assert(rows_in_enum_order(), "classification rows must follow the ChangeKind declaration order");

}  // namespace

std::span<const ChangeKindInfo> change_kinds() { return table; }

const ChangeKindInfo& info(ChangeKind kind) { return table[static_cast<std::size_t>(kind)]; }

std::string_view to_string(ChangeKind kind) { return info(kind).id; }

ChangeClass classify(ChangeKind kind, RevisionContext context) {
    const ChangeClass base = info(kind).change_class;
    if (context == RevisionContext::added_revision && base == ChangeClass::breaking) return ChangeClass::compatible;
    return base;
}

bool is_error(ChangeKind kind) { return kind == ChangeKind::revision_not_changed; }

std::string_view to_string(ChangeClass change_class) {
    switch (change_class) {
        case ChangeClass::cosmetic: return "cosmetic";
        case ChangeClass::compatible: return "compatible";
        case ChangeClass::breaking: return "breaking";
    }
    return "cosmetic";
}

std::string_view to_string(Verdict verdict) {
    switch (verdict) {
        case Verdict::identical: return "identical";
        case Verdict::cosmetic: return "cosmetic";
        case Verdict::compatible: return "compatible";
        case Verdict::breaking: return "breaking";
    }
    return "identical";
}

Verdict verdict_of(ChangeClass change_class) {
    switch (change_class) {
        case ChangeClass::cosmetic: return Verdict::cosmetic;
        case ChangeClass::compatible: return Verdict::compatible;
        case ChangeClass::breaking: return Verdict::breaking;
    }
    return Verdict::cosmetic;
}

}  // namespace esi
