// Child elements per element, in ETG.2000 schema 1.17 order (EtherCATInfo.xsd, EtherCATBase.xsd,
// EtherCATDict.xsd). The writer places children in the same order (src/xml/writer_*.cpp).

#include "navigate/schema_children.hpp"

#include <array>

namespace esi::navigate {

namespace {

using Names = std::span<const std::string_view>;

constexpr std::string_view info_list[] = {"EtherCATInfo"};
constexpr std::string_view info[] = {"InfoReference", "Vendor", "Descriptions"};
constexpr std::string_view module_root[] = {"Vendor", "Modules"};
constexpr std::string_view vendor[] = {"Id", "Name", "Comment", "URL", "DescriptionURL", "Image16x14", "ImageFile16x14",
                                       "ImageData16x14", "VendorSpecific"};
constexpr std::string_view descriptions[] = {"Groups", "Devices", "Modules"};
constexpr std::string_view groups[] = {"Group"};
constexpr std::string_view group[] = {"Type", "Name", "Comment", "Image16x14", "ImageFile16x14", "ImageData16x14",
                                      "VendorSpecific"};
constexpr std::string_view devices[] = {"Device"};
constexpr std::string_view modules[] = {"Module"};
constexpr std::string_view device[] = {"Sci", "Type", "HideType", "AlternativeType", "SubDevice", "Name", "Comment", "URL",
                                       "Info", "GroupType", "Profile", "Fmmu", "Sm", "Su", "RxPdo", "TxPdo", "Mailbox",
                                       "Dc", "Slots", "ESC", "Eeprom", "Image16x14", "ImageFile16x14", "ImageData16x14",
                                       "VendorSpecific"};
constexpr std::string_view module[] = {"Type", "Name", "RxPdo", "TxPdo", "SafetyParaMapping", "Mailbox", "Profile",
                                       "DcOpModeName", "Image16x14", "ImageFile16x14", "ImageData16x14", "VendorSpecific"};
constexpr std::string_view profile[] = {"ProfileNo", "AddInfo", "SubAddInfo", "ChannelCount", "ChannelInfo",
                                        "DictionaryFile", "Dictionary", "DiagFile", "DiagMessages", "VendorSpecific"};
constexpr std::string_view dictionary[] = {"UnitTypes", "DataTypes", "Objects"};
constexpr std::string_view data_types[] = {"DataType"};
constexpr std::string_view data_type[] = {"Index", "Name", "BaseType", "Comment", "BitSize", "ArrayInfo", "SubItem",
                                          "EnumInfo", "Properties", "Xml"};
constexpr std::string_view array_info[] = {"LBound", "Elements"};
constexpr std::string_view type_sub_item[] = {"SubIdx", "Name", "DisplayName", "Type", "Comment", "BitSize", "BitOffs",
                                              "DefaultString", "DefaultData", "MinValue", "MaxValue", "DefaultValue",
                                              "Flags", "Property", "Xml"};
constexpr std::string_view objects[] = {"Object"};
constexpr std::string_view object[] = {"Index", "Name", "Comment", "Type", "BitSize", "Info", "Flags", "Properties", "Xml"};
constexpr std::string_view object_info[] = {"DefaultString", "MinData", "MaxData", "DefaultData", "MinValue", "MaxValue",
                                            "DefaultValue", "SubItem", "DisplayName", "Unit"};
constexpr std::string_view info_sub_item[] = {"Name", "Info"};
constexpr std::string_view flags[] = {"Access", "Category", "PdoMapping", "SafetyMapping", "Attribute", "Transition",
                                      "SdoAccess", "Backup", "Setting"};
constexpr std::string_view pdo[] = {"Index", "Name", "Exclude", "Entry", "ExcludedSm"};
constexpr std::string_view entry[] = {"Index", "SubIndex", "BitLen", "Name", "Comment", "DataType"};
constexpr std::string_view mailbox[] = {"AoE", "EoE", "CoE", "FoE", "SoE", "VoE", "VendorSpecific"};
constexpr std::string_view coe[] = {"Object", "InitCmd"};
constexpr std::string_view init_cmd[] = {"Transition", "Index", "SubIndex", "Data", "Comment"};
constexpr std::string_view dc[] = {"OpMode", "VendorSpecific"};
constexpr std::string_view op_mode[] = {"Name", "Desc", "AssignActivate", "CycleTimeSync0", "ShiftTimeSync0",
                                        "CycleTimeSync1", "ShiftTimeSync1", "Sm", "VendorSpecific"};
constexpr std::string_view op_mode_sm[] = {"Pdo"};
constexpr std::string_view slots[] = {"Slot", "SlotGroupData", "ModulePdoGroup", "SlotSelections"};
constexpr std::string_view slot[] = {"Name", "ModuleIdent", "ModuleClass", "Image16x14", "ImageFile16x14", "ImageData16x14"};
constexpr std::string_view eeprom[] = {"Data", "ByteSize", "ConfigData", "BootStrap", "Category", "VendorSpecific"};
constexpr std::string_view category[] = {"CatNo", "Data", "DataString", "DataUINT", "DataUDINT"};

struct Entry {
    std::string_view parent;
    std::string_view grandparent;  // empty: any
    Names children;
};

// Entries with a grandparent come before the entry of the same name without one.
constexpr std::array table = {
    Entry{"EtherCATInfoList", "", info_list},
    Entry{"EtherCATInfo", "", info},
    Entry{"EtherCATModule", "", module_root},
    Entry{"Vendor", "", vendor},
    Entry{"Descriptions", "", descriptions},
    Entry{"Groups", "", groups},
    Entry{"Group", "", group},
    Entry{"Devices", "", devices},
    Entry{"Modules", "", modules},
    Entry{"Device", "", device},
    Entry{"Module", "", module},
    Entry{"Profile", "", profile},
    Entry{"Dictionary", "", dictionary},
    Entry{"DataTypes", "", data_types},
    Entry{"DataType", "DataTypes", data_type},
    Entry{"ArrayInfo", "", array_info},
    Entry{"SubItem", "DataType", type_sub_item},
    Entry{"SubItem", "Info", info_sub_item},
    Entry{"Objects", "", objects},
    Entry{"Object", "Objects", object},
    Entry{"Info", "Object", object_info},
    Entry{"Info", "SubItem", object_info},
    Entry{"Flags", "", flags},
    Entry{"RxPdo", "", pdo},
    Entry{"TxPdo", "", pdo},
    Entry{"Entry", "", entry},
    Entry{"Mailbox", "", mailbox},
    Entry{"CoE", "", coe},
    Entry{"InitCmd", "CoE", init_cmd},
    Entry{"Dc", "", dc},
    Entry{"OpMode", "Dc", op_mode},
    Entry{"Sm", "OpMode", op_mode_sm},
    Entry{"Slots", "", slots},
    Entry{"Slot", "", slot},
    Entry{"Eeprom", "", eeprom},
    Entry{"Category", "Eeprom", category},
};

}  // namespace

std::span<const std::string_view> schema_children(std::string_view parent, std::string_view grandparent) {
    for (const Entry& entry : table)
        if (entry.parent == parent && (entry.grandparent.empty() || entry.grandparent == grandparent)) return entry.children;
    return {};
}

}  // namespace esi::navigate
