// One focused case per change kind: the base file and a copy that differs in one thing; the
// differ must report that kind, with its class, at its path, and nothing else (a breaking change
// under the same RevisionNo also brings the revision-not-changed error).

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "diff_fixture.hpp"

namespace {

using esi::ChangeClass;
using esi::ChangeKind;
using esi::test::diff_base;
using esi::test::edit;
using Edits = std::vector<std::pair<std::string, std::string>>;

struct Case {
    const char* name;
    Edits old_edits;
    Edits new_edits;
    ChangeKind kind;
    ChangeClass change_class;
    std::string path;
    std::vector<ChangeKind> also = {};      // other kinds the edit necessarily brings
    std::optional<bool> revision_error = {};  // default: expected exactly when the class is breaking
};

const std::string added_device = R"(<Device Physics="YY"><Type ProductCode="#x00003003" RevisionNo="1">EX-3003</Type><Name>Third</Name><GroupType>IO</GroupType></Device></Devices>)";
const std::string second_device_rev2 = R"(<Device Physics="KK">
        <Type ProductCode="#x00002002" RevisionNo="#x00020000">EX-2002</Type>
        <Name LcId="1033">Second device</Name>
        <GroupType>IO</GroupType>
        <Sm StartAddress="#x1000" ControlByte="#x24" DefaultSize="1" Enable="1">Outputs</Sm>
        <RxPdo Fixed="true" Sm="0">
          <Index>#x1600</Index>
          <Name>Out</Name>
          <Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen><Name>Bit</Name><DataType>BOOL</DataType></Entry>
        </RxPdo>
      </Device>
    </Devices>)";
const std::string status_pdo = R"(<TxPdo Sm="3">
          <Index>#x1A01</Index>
          <Name>Status</Name>
          <Entry>
            <Index>#x6010</Index>
            <SubIndex>1</SubIndex>
            <BitLen>16</BitLen>
            <Name>Status word</Name>
            <DataType>UINT</DataType>
          </Entry>
        </TxPdo>
        )";
const std::string inputs_pdo_start = "<TxPdo Sm=\"3\">\n          <Index>#x1A00</Index>";
const std::string input_a = R"(<Entry>
            <Index>#x6000</Index>
            <SubIndex>1</SubIndex>
            <BitLen>8</BitLen>
            <Name>Input A</Name>
            <DataType>USINT</DataType>
          </Entry>
          )";
const std::string init_cmd_filter = R"(<InitCmd>
              <Transition>PS</Transition>
              <Index>#x8000</Index>
              <SubIndex>1</SubIndex>
              <Data>64000000</Data>
              <Comment>filter</Comment>
            </InitCmd>
            )";
const std::string second_device_pdo_end = "<DataType>BOOL</DataType></Entry>\n        </RxPdo>";
const std::string extra_object = "<Object><Index>#x9000</Index><Name>New</Name><Type>USINT</Type><BitSize>8</BitSize></Object></Objects>";
const std::string dt9000 = "<DataTypes><DataType><Name>DT9000</Name><BitSize>8</BitSize></DataType>";
const std::string gain_item =
    R"(<Flags><Access>rw</Access><PdoMapping>R</PdoMapping></Flags></SubItem>
                <SubItem><SubIdx>2</SubIdx><Name>Gain</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>48</BitOffs></SubItem>)";
const std::string filter_flags_end = "<Flags><Access>rw</Access><PdoMapping>R</PdoMapping></Flags></SubItem>";

std::vector<Case> cases() {
    using K = ChangeKind;
    using C = ChangeClass;
    return {
        // ---- file as a whole
        {"DocumentKind",
         {},
         {{"<EtherCATInfo Version=\"1.17\">", "<EtherCATInfoList><EtherCATInfo Version=\"1.17\">"},
          {"</EtherCATInfo>", "</EtherCATInfo></EtherCATInfoList>"}},
         K::document_kind_changed, C::cosmetic, ""},
        {"InfoVersion", {}, {{"Version=\"1.17\"", "Version=\"1.16\""}}, K::info_version_changed, C::cosmetic, "EtherCATInfo@Version"},
        {"VendorId", {}, {{"<Id>#x00000E4A</Id>", "<Id>#x00000E4B</Id>"}}, K::vendor_id_changed, C::breaking, "Vendor/Id", {}, false},
        {"VendorFileVersion", {}, {{"FileVersion=\"3\"", "FileVersion=\"4\""}}, K::vendor_changed, C::cosmetic, "Vendor@FileVersion"},
        {"GroupAdded", {}, {{"<Groups>", "<Groups><Group><Type>Extra</Type><Name>Extra</Name></Group>"}}, K::group_added, C::cosmetic, "Group[Extra]"},
        {"GroupRemoved", {{"<Groups>", "<Groups><Group><Type>Extra</Type><Name>Extra</Name></Group>"}}, {}, K::group_removed, C::cosmetic, "Group[Extra]"},
        {"GroupSortOrder", {}, {{"SortOrder=\"1\"", "SortOrder=\"2\""}}, K::group_changed, C::cosmetic, "Group[IO]@SortOrder"},
        {"ModuleAdded", {}, {{"</Modules>", "<Module><Type ModuleIdent=\"#x00001300\">AX-1300</Type><Name>Third</Name></Module></Modules>"}},
         K::module_added, C::compatible, "Modules/Module[#x00001300]"},
        {"ModuleRemovedNotInAnySlot", {{"</Modules>", "<Module><Type ModuleIdent=\"#x00001300\">AX-1300</Type><Name>Third</Name></Module></Modules>"}}, {},
         K::module_removed, C::breaking, "Modules/Module[#x00001300]", {}, false},
        {"ModuleClassOfASlotModule", {}, {{"ModuleClass=\"Axis\">AX-1100", "ModuleClass=\"Servo\">AX-1100"}}, K::module_attribute_changed,
         C::breaking, "Modules/Module[#x00001100]/Type@ModuleClass", {}, true},

        // ---- device identity and description
        {"DeviceAdded", {}, {{"</Devices>", added_device}}, K::device_added, C::compatible, "Device"},
        {"DeviceRemoved", {{"</Devices>", added_device}}, {}, K::device_removed, C::breaking, "Device", {}, false},
        {"RevisionAddedNextToOld", {}, {{"</Devices>", second_device_rev2}}, K::device_revision_added, C::compatible, "Type@RevisionNo"},
        {"RevisionReplaced", {}, {{"RevisionNo=\"#x00010000\">EX-2002", "RevisionNo=\"#x00020000\">EX-2002"}}, K::revision_changed,
         C::compatible, "Type@RevisionNo"},
        {"RevisionNotChanged", {}, {{"<BitLen>4</BitLen>", "<BitLen>8</BitLen>"}}, K::revision_not_changed, C::breaking, "Type@RevisionNo",
         {K::pdo_entry_bit_len_changed}},
        {"TypeText", {}, {{">EX-1001</Type>", ">EX-1001-B</Type>"}}, K::type_text_changed, C::cosmetic, "Type"},
        {"NameGerman", {}, {{"Beispielgerät", "Beispiel"}}, K::name_changed, C::cosmetic, "Name[1031]"},
        {"Comment", {}, {{"A device for tests", "A test device"}}, K::comment_changed, C::cosmetic, "Comment[1033]"},
        {"Image", {}, {{"<ImageData16x14>424D<", "<ImageData16x14>424E<"}}, K::image_changed, C::cosmetic, "ImageData16x14"},
        {"GroupType", {}, {{"<GroupType>IO</GroupType>\n        <Profile>", "<GroupType>Drives</GroupType>\n        <Profile>"}},
         K::group_type_changed, C::cosmetic, "GroupType"},
        {"PhysicsChanged", {}, {{"<Device Physics=\"YY\">", "<Device Physics=\"YK\">"}}, K::physics_changed, C::breaking, "@Physics"},
        {"PhysicsPortAdded", {}, {{"<Device Physics=\"YY\">", "<Device Physics=\"YYY\">"}}, K::physics_ports_added, C::compatible, "@Physics"},
        {"Invisible", {}, {{"<Device Physics=\"YY\">", "<Device Physics=\"YY\" Invisible=\"true\">"}}, K::device_flag_changed, C::cosmetic,
         "@Invisible"},
        {"ProfileNo", {}, {{"<ProfileNo>5001</ProfileNo>", "<ProfileNo>402</ProfileNo>"}}, K::profile_number_changed, C::breaking,
         "Profile/ProfileNo"},
        {"ProfileAddInfo", {}, {{"<ProfileNo>5001</ProfileNo>", "<ProfileNo>5001</ProfileNo><AddInfo>3</AddInfo>"}}, K::profile_changed,
         C::compatible, "Profile/AddInfo"},

        // ---- SyncManagers, FMMUs, sync units
        {"SmAdded", {}, {{"<Su>Main</Su>", "<Sm StartAddress=\"#x1800\" ControlByte=\"#x20\" Enable=\"0\">Inputs</Sm><Su>Main</Su>"}},
         K::sm_added, C::breaking, "Sm[4]"},
        {"SmRemoved", {{"<Su>Main</Su>", "<Sm StartAddress=\"#x1800\" ControlByte=\"#x20\" Enable=\"0\">Inputs</Sm><Su>Main</Su>"}}, {},
         K::sm_removed, C::breaking, "Sm[4]"},
        {"SmTypeDeclared", {{"Enable=\"1\">Inputs</Sm>", "Enable=\"1\"></Sm>"}}, {}, K::sm_type_declared, C::compatible, "Sm[3]"},
        {"SmTypeChanged", {}, {{"Enable=\"1\">Inputs</Sm>", "Enable=\"1\">MBoxIn</Sm>"}}, K::sm_type_changed, C::breaking, "Sm[3]"},
        {"SmAddress", {}, {{"StartAddress=\"#x1400\"", "StartAddress=\"#x1500\""}}, K::sm_address_changed, C::breaking, "Sm[3]@StartAddress"},
        {"SmControlByte", {}, {{"ControlByte=\"#x64\"", "ControlByte=\"#x24\""}}, K::sm_control_byte_changed, C::breaking, "Sm[2]@ControlByte"},
        {"SmDefaultSize", {}, {{"ControlByte=\"#x64\" DefaultSize=\"2\"", "ControlByte=\"#x64\" DefaultSize=\"4\""}}, K::sm_size_changed,
         C::breaking, "Sm[2]@DefaultSize"},
        {"SmMaxSizeWidened", {}, {{"ControlByte=\"#x26\" DefaultSize=\"128\" MinSize=\"34\" MaxSize=\"256\"", "ControlByte=\"#x26\" DefaultSize=\"128\" MinSize=\"34\" MaxSize=\"512\""}},
         K::sm_size_limits_widened, C::compatible, "Sm[0]@MaxSize"},
        {"SmMaxSizeNarrowed", {}, {{"ControlByte=\"#x26\" DefaultSize=\"128\" MinSize=\"34\" MaxSize=\"256\"", "ControlByte=\"#x26\" DefaultSize=\"128\" MinSize=\"34\" MaxSize=\"128\""}},
         K::sm_size_limits_narrowed, C::breaking, "Sm[0]@MaxSize"},
        {"SmEnable", {}, {{"DefaultSize=\"2\" Enable=\"1\">Outputs", "DefaultSize=\"2\" Enable=\"0\">Outputs"}}, K::sm_enable_changed, C::breaking,
         "Sm[2]@Enable"},
        {"SmWatchdog", {}, {{"<Sm StartAddress=\"#x1100\"", "<Sm Watchdog=\"true\" StartAddress=\"#x1100\""}}, K::sm_flag_changed, C::breaking,
         "Sm[2]@Watchdog"},
        {"FmmuAdded", {}, {{"<Fmmu>Inputs</Fmmu>", "<Fmmu>Inputs</Fmmu><Fmmu>MBoxState</Fmmu>"}}, K::fmmu_added, C::compatible, "Fmmu[2]"},
        {"FmmuRemoved", {{"<Fmmu>Inputs</Fmmu>", "<Fmmu>Inputs</Fmmu><Fmmu>MBoxState</Fmmu>"}}, {}, K::fmmu_removed, C::breaking, "Fmmu[2]"},
        {"FmmuSm", {}, {{"<Fmmu>Outputs</Fmmu>", "<Fmmu Sm=\"2\">Outputs</Fmmu>"}}, K::fmmu_changed, C::breaking, "Fmmu[0]@Sm"},
        {"SuAdded", {}, {{"<Su>Main</Su>", "<Su>Main</Su><Su>Second</Su>"}}, K::sync_unit_added, C::compatible, "Su[1]"},
        {"SuRemoved", {{"<Su>Main</Su>", "<Su>Main</Su><Su>Second</Su>"}}, {}, K::sync_unit_removed, C::breaking, "Su[1]"},
        {"SuSeparate", {}, {{"<Su>Main</Su>", "<Su SeparateSu=\"true\">Main</Su>"}}, K::sync_unit_changed, C::breaking, "Su[0]@SeparateSu"},

        // ---- PDOs
        {"PdoAdded", {}, {{"<Mailbox DataLinkLayer", "<TxPdo><Index>#x1A11</Index><Name>Extra</Name></TxPdo><Mailbox DataLinkLayer"}},
         K::pdo_added, C::compatible, "TxPdo[#x1A11]"},
        {"PdoAddedAssigned", {}, {{"<Mailbox DataLinkLayer", "<TxPdo Sm=\"3\"><Index>#x1A11</Index><Name>Extra</Name></TxPdo><Mailbox DataLinkLayer"}},
         K::pdo_added_assigned, C::breaking, "TxPdo[#x1A11]"},
        {"PdoRemoved", {{"<Mailbox DataLinkLayer", "<TxPdo><Index>#x1A11</Index><Name>Extra</Name></TxPdo><Mailbox DataLinkLayer"}}, {},
         K::pdo_removed, C::breaking, "TxPdo[#x1A11]"},
        {"PdoSm", {}, {{"<TxPdo>\n          <Index>#x1A10</Index>", "<TxPdo Sm=\"3\">\n          <Index>#x1A10</Index>"}}, K::pdo_sm_changed,
         C::breaking, "TxPdo[#x1A10]@Sm"},
        {"SmAssignmentOrder", {}, {{status_pdo, ""}, {inputs_pdo_start, status_pdo + inputs_pdo_start}}, K::sm_assignment_order_changed,
         C::breaking, "Sm[3]/TxPdoAssignment"},
        {"PdoFixedSet", {}, {{inputs_pdo_start, "<TxPdo Sm=\"3\" Fixed=\"1\">\n          <Index>#x1A00</Index>"}}, K::pdo_fixed_set, C::breaking,
         "TxPdo[#x1A00]@Fixed"},
        {"PdoFixedCleared", {}, {{"<RxPdo Fixed=\"true\" Sm=\"2\">", "<RxPdo Sm=\"2\">"}}, K::pdo_fixed_cleared, C::compatible,
         "RxPdo[#x1600]@Fixed"},
        {"PdoMandatorySet", {}, {{"<RxPdo Fixed=\"true\" Sm=\"2\">", "<RxPdo Fixed=\"true\" Mandatory=\"1\" Sm=\"2\">"}}, K::pdo_mandatory_set,
         C::breaking, "RxPdo[#x1600]@Mandatory"},
        {"PdoMandatoryCleared", {{"<RxPdo Fixed=\"true\" Sm=\"2\">", "<RxPdo Fixed=\"true\" Mandatory=\"1\" Sm=\"2\">"}}, {},
         K::pdo_mandatory_cleared, C::compatible, "RxPdo[#x1600]@Mandatory"},
        {"PdoExcludeAdded", {}, {{"<Name>Status</Name>", "<Name>Status</Name><Exclude>#x1A10</Exclude>"}}, K::pdo_exclude_added, C::breaking,
         "TxPdo[#x1A01]/Exclude[#x1A10]"},
        {"PdoExcludeRemoved", {}, {{"<Exclude>#x1A10</Exclude>", ""}}, K::pdo_exclude_removed, C::compatible, "TxPdo[#x1A00]/Exclude[#x1A10]"},
        {"PdoOversampling", {}, {{"<TxPdo Sm=\"3\">\n          <Index>#x1A01</Index>", "<TxPdo Sm=\"3\" OSFac=\"2\">\n          <Index>#x1A01</Index>"}},
         K::pdo_attribute_changed, C::breaking, "TxPdo[#x1A01]@OSFac"},
        {"EntryAdded", {}, {{"<Name>Status word</Name>\n            <DataType>UINT</DataType>\n          </Entry>",
                             "<Name>Status word</Name>\n            <DataType>UINT</DataType>\n          </Entry><Entry><Index>#x6010</Index><SubIndex>2</SubIndex><BitLen>8</BitLen><Name>Extra</Name></Entry>"}},
         K::pdo_entry_added, C::breaking, "TxPdo[#x1A01]/Entry[#x6010:02]"},
        {"EntryRemoved", {{"<Name>Status word</Name>\n            <DataType>UINT</DataType>\n          </Entry>",
                           "<Name>Status word</Name>\n            <DataType>UINT</DataType>\n          </Entry><Entry><Index>#x6010</Index><SubIndex>2</SubIndex><BitLen>8</BitLen><Name>Extra</Name></Entry>"}},
         {}, K::pdo_entry_removed, C::breaking, "TxPdo[#x1A01]/Entry[#x6010:02]"},
        {"EntryMoved", {}, {{input_a, ""}, {"<Entry>\n            <Index>0</Index>", input_a + "<Entry>\n            <Index>0</Index>"}},
         K::pdo_entry_moved, C::breaking, "TxPdo[#x1A00]/Entry[#x6000:01]"},
        {"EntryIndex", {}, {{"<SubIndex>2</SubIndex>\n            <BitLen>8</BitLen>\n            <Name>Input B</Name>", "<SubIndex>3</SubIndex>\n            <BitLen>8</BitLen>\n            <Name>Input B</Name>"}},
         K::pdo_entry_index_changed, C::breaking, "TxPdo[#x1A00]/Entry[#x6000:02]/Index"},
        {"EntryBitLen", {}, {{"<BitLen>4</BitLen>", "<BitLen>8</BitLen>"}}, K::pdo_entry_bit_len_changed, C::breaking, "TxPdo[#x1A00]/Entry[3]/BitLen"},
        {"EntryDataType", {}, {{"<Name>Output value</Name>\n            <DataType>UINT</DataType>", "<Name>Output value</Name>\n            <DataType>INT</DataType>"}},
         K::pdo_entry_data_type_changed, C::breaking, "RxPdo[#x1600]/Entry[#x7000:00]/DataType"},
        {"EntryDataTypeDropped", {}, {{"<Name>Diag code</Name>\n            <DataType>UDINT</DataType>", "<Name>Diag code</Name>"}},
         K::pdo_entry_data_type_declared, C::compatible, "TxPdo[#x1A10]/Entry[#x6020:01]/DataType"},
        {"EntrySwapData", {}, {{"<Name>Diag code</Name>\n            <DataType>UDINT</DataType>", "<Name>Diag code</Name>\n            <DataType SwapData=\"1\">UDINT</DataType>"}},
         K::pdo_entry_attribute_changed, C::breaking, "TxPdo[#x1A10]/Entry[#x6020:01]/DataType@SwapData"},

        // ---- object dictionary
        {"ObjectAdded", {}, {{"</Objects>", extra_object}}, K::object_added, C::compatible, "Dictionary/Object[#x9000]"},
        {"ObjectRemoved", {{"</Objects>", extra_object}}, {}, K::object_removed, C::breaking, "Dictionary/Object[#x9000]"},
        {"ObjectCode", {}, {{"<Type>USINT</Type>\n                <BitSize>8</BitSize>\n                <Flags><Access>ro</Access><PdoMapping>T</PdoMapping>",
                             "<Type>ARRAY [1..1] OF USINT</Type>\n                <BitSize>24</BitSize>\n                <Flags><Access>ro</Access><PdoMapping>T</PdoMapping>"}},
         K::object_code_changed, C::breaking, "Dictionary/Object[#x6000]/ObjectCode", {K::object_size_changed, K::object_entry_added, K::name_changed}},
        {"ObjectSize", {}, {{"<Type>UINT</Type>\n                <BitSize>16</BitSize>", "<Type>UINT</Type>\n                <BitSize>32</BitSize>"}},
         K::object_size_changed, C::breaking, "Dictionary/Object[#x7000]/BitSize"},
        {"ObjectEntryAdded", {}, {{filter_flags_end, gain_item}}, K::object_entry_added, C::compatible, "Dictionary/Object[#x8000:02]",
         {K::data_type_changed}},
        {"ObjectEntryRemoved", {{filter_flags_end, gain_item}}, {}, K::object_entry_removed, C::breaking, "Dictionary/Object[#x8000:02]",
         {K::data_type_changed}},
        {"ObjectEntryType", {}, {{"<Name>Filter</Name><Type>UDINT</Type>", "<Name>Filter</Name><Type>DINT</Type>"}}, K::object_entry_type_changed,
         C::breaking, "Dictionary/Object[#x8000:01]/Type", {K::data_type_changed}},
        {"ObjectEntryOffset", {}, {{"<BitSize>32</BitSize><BitOffs>16</BitOffs><Flags><Access>rw</Access>", "<BitSize>32</BitSize><BitOffs>24</BitOffs><Flags><Access>rw</Access>"}},
         K::object_entry_offset_changed, C::breaking, "Dictionary/Object[#x8000:01]/BitOffs", {K::data_type_changed}},
        {"AccessNarrowed", {}, {{"<Access>rw</Access><PdoMapping>R</PdoMapping><Category>o</Category>", "<Access>ro</Access><PdoMapping>R</PdoMapping><Category>o</Category>"}},
         K::object_access_narrowed, C::breaking, "Dictionary/Object[#x7000]/Flags/Access"},
        {"AccessRestricted", {}, {{"<Access>rw</Access><PdoMapping>R</PdoMapping><Category>o</Category>", "<Access WriteRestrictions=\"PreOP\">rw</Access><PdoMapping>R</PdoMapping><Category>o</Category>"}},
         K::object_access_narrowed, C::breaking, "Dictionary/Object[#x7000]/Flags/Access"},
        {"AccessWidened", {}, {{"<Access>ro</Access><PdoMapping>T</PdoMapping></Flags>", "<Access>rw</Access><PdoMapping>T</PdoMapping></Flags>"}},
         K::object_access_widened, C::compatible, "Dictionary/Object[#x6000]/Flags/Access"},
        {"PdoMappingRemoved", {}, {{"<Access>ro</Access><PdoMapping>T</PdoMapping></Flags>", "<Access>ro</Access></Flags>"}},
         K::object_pdo_mapping_removed, C::breaking, "Dictionary/Object[#x6000]/Flags/PdoMapping"},
        {"PdoMappingAdded", {}, {{"<Access>ro</Access><PdoMapping>T</PdoMapping></Flags>", "<Access>ro</Access><PdoMapping>RT</PdoMapping></Flags>"}},
         K::object_pdo_mapping_added, C::compatible, "Dictionary/Object[#x6000]/Flags/PdoMapping"},
        {"DefaultValue", {}, {{"<DefaultValue>5</DefaultValue>", "<DefaultValue>6</DefaultValue>"}}, K::object_default_changed, C::compatible,
         "Dictionary/Object[#x7000]/Default"},
        {"MappingDefault", {}, {{"#x60000208", "#x60000308"}}, K::pdo_mapping_default_changed, C::breaking, "Dictionary/Object[#x1A00:02]/Default"},
        {"MaxNarrowed", {}, {{"<MaxValue>1000</MaxValue>", "<MaxValue>500</MaxValue>"}}, K::object_limits_narrowed, C::breaking,
         "Dictionary/Object[#x7000]/Max"},
        {"MinAdded", {}, {{"<MinValue>0</MinValue>", "<MinValue>1</MinValue>"}}, K::object_limits_narrowed, C::breaking, "Dictionary/Object[#x7000]/Min"},
        {"MinDeclaredAtTypeBound", {{"<MinValue>0</MinValue>", ""}}, {}, K::object_limits_widened, C::compatible, "Dictionary/Object[#x7000]/Min"},
        {"MaxWidened", {}, {{"<MaxValue>1000</MaxValue>", "<MaxValue>2000</MaxValue>"}}, K::object_limits_widened, C::compatible,
         "Dictionary/Object[#x7000]/Max"},
        {"MaxUnordered", {}, {{"<MaxValue>1000</MaxValue>", "<MaxData>E80300000000000001</MaxData>"}}, K::object_limits_changed, C::breaking,
         "Dictionary/Object[#x7000]/Max"},
        {"Category", {}, {{"<Category>o</Category>", "<Category>m</Category>"}}, K::object_flags_changed, C::compatible,
         "Dictionary/Object[#x7000]/Flags/Category"},
        {"DataTypeAdded", {}, {{"<DataTypes>", dt9000}}, K::data_type_added, C::compatible, "Dictionary/DataType[DT9000]"},
        {"DataTypeRemoved", {{"<DataTypes>", dt9000}}, {}, K::data_type_removed, C::compatible, "Dictionary/DataType[DT9000]"},
        {"DataTypeChanged", {{"<DataTypes>", dt9000}}, {{"<DataTypes>", "<DataTypes><DataType><Name>DT9000</Name><BitSize>16</BitSize></DataType>"}},
         K::data_type_changed, C::compatible, "Dictionary/DataType[DT9000]"},
        {"DataTypeComment", {{"<DataTypes>", "<DataTypes><DataType><Name>DT9000</Name><Comment>a</Comment><BitSize>8</BitSize></DataType>"}},
         {{"<DataTypes>", "<DataTypes><DataType><Name>DT9000</Name><Comment>b</Comment><BitSize>8</BitSize></DataType>"}}, K::data_type_text_changed,
         C::cosmetic, "Dictionary/DataType[DT9000]"},

        // ---- mailbox and InitCmds
        {"MailboxAdded", {}, {{second_device_pdo_end, second_device_pdo_end + "<Mailbox><CoE/></Mailbox>"}}, K::mailbox_added, C::compatible,
         "Mailbox"},
        {"MailboxRemoved", {{second_device_pdo_end, second_device_pdo_end + "<Mailbox><CoE/></Mailbox>"}}, {}, K::mailbox_removed, C::breaking,
         "Mailbox"},
        {"ProtocolAdded", {}, {{"<FoE/>", "<FoE/><VoE/>"}}, K::mailbox_protocol_added, C::compatible, "Mailbox/VoE"},
        {"ProtocolRemoved", {}, {{"<EoE IP=\"true\"/>", ""}}, K::mailbox_protocol_removed, C::breaking, "Mailbox/EoE"},
        {"CoeFlagSet", {}, {{"CompleteAccess=\"false\">", "CompleteAccess=\"true\">"}}, K::mailbox_flag_set, C::compatible,
         "Mailbox/CoE@CompleteAccess"},
        {"CoeFlagCleared", {}, {{"PdoAssign=\"true\"", "PdoAssign=\"false\""}}, K::mailbox_flag_cleared, C::breaking, "Mailbox/CoE@PdoAssign"},
        {"EoeFlagCleared", {}, {{"<EoE IP=\"true\"/>", "<EoE/>"}}, K::mailbox_flag_cleared, C::breaking, "Mailbox/EoE@IP"},
        {"Ds402Channels", {}, {{"<CoE SdoInfo=\"true\"", "<CoE DS402Channels=\"2\" SdoInfo=\"true\""}}, K::mailbox_channels_changed, C::breaking,
         "Mailbox/CoE@DS402Channels"},
        {"PdoUpload", {}, {{"<CoE SdoInfo=\"true\"", "<CoE PdoUpload=\"true\" SdoInfo=\"true\""}}, K::mailbox_attribute_changed, C::compatible,
         "Mailbox/CoE@PdoUpload"},
        {"InitCmdAdded", {}, {{init_cmd_filter, init_cmd_filter + "<InitCmd><Transition>PS</Transition><Index>#x7000</Index><SubIndex>0</SubIndex><Data>0500</Data></InitCmd>"}},
         K::init_cmd_added, C::breaking, "Mailbox/CoE/InitCmd[#x7000:00]"},
        {"InitCmdRemoved", {{init_cmd_filter, init_cmd_filter + "<InitCmd><Transition>PS</Transition><Index>#x7000</Index><SubIndex>0</SubIndex><Data>0500</Data></InitCmd>"}}, {},
         K::init_cmd_removed, C::breaking, "Mailbox/CoE/InitCmd[#x7000:00]"},
        {"InitCmdData", {}, {{"<Data>64000000</Data>", "<Data>C8000000</Data>"}}, K::init_cmd_changed, C::breaking, "Mailbox/CoE/InitCmd[#x8000:01]/Data"},
        {"InitCmdTransition", {}, {{"<Transition>PS</Transition>\n              <Index>#x8000</Index>", "<Transition>IP</Transition>\n              <Index>#x8000</Index>"}},
         K::init_cmd_changed, C::breaking, "Mailbox/CoE/InitCmd[#x8000:01]/Transition"},
        {"InitCmdOrder", {}, {{init_cmd_filter, ""}, {"</CoE>", init_cmd_filter + "</CoE>"}}, K::init_cmd_order_changed, C::breaking,
         "Mailbox/CoE/InitCmd[#x8000:01]"},
        {"InitCmdComment", {}, {{"<Comment>filter</Comment>", "<Comment>input filter</Comment>"}}, K::comment_changed, C::cosmetic,
         "Mailbox/CoE/InitCmd[#x8000:01]/Comment"},

        // ---- distributed clocks
        {"DcModeAdded", {}, {{"</Dc>", "<OpMode><Name>Sync1</Name><AssignActivate>#x0700</AssignActivate></OpMode></Dc>"}}, K::dc_op_mode_added,
         C::compatible, "Dc/OpMode[Sync1]"},
        {"DcModeRemoved", {{"</Dc>", "<OpMode><Name>Sync1</Name><AssignActivate>#x0700</AssignActivate></OpMode></Dc>"}}, {}, K::dc_op_mode_removed,
         C::breaking, "Dc/OpMode[Sync1]"},
        {"AssignActivate", {}, {{"<AssignActivate>#x0300</AssignActivate>", "<AssignActivate>#x0700</AssignActivate>"}},
         K::dc_assign_activate_changed, C::breaking, "Dc/OpMode[DC]/AssignActivate"},
        {"ShiftTime", {}, {{"<ShiftTimeSync0>0</ShiftTimeSync0>", "<ShiftTimeSync0>1000</ShiftTimeSync0>"}}, K::dc_timing_changed, C::breaking,
         "Dc/OpMode[DC]/ShiftTimeSync0"},
        {"DcDesc", {}, {{"<Desc>Free run</Desc>", "<Desc>Free running</Desc>"}}, K::comment_changed, C::cosmetic, "Dc/OpMode[FreeRun]/Desc"},
        {"DcAttribute", {}, {{"<Dc>", "<Dc ExternalRefClock=\"true\">"}}, K::dc_attribute_changed, C::breaking, "Dc@ExternalRefClock"},

        // ---- EEPROM
        {"EepromAdded", {}, {{second_device_pdo_end, second_device_pdo_end + "<Eeprom><ByteSize>256</ByteSize></Eeprom>"}}, K::eeprom_added,
         C::compatible, "Eeprom"},
        {"EepromRemoved", {{second_device_pdo_end, second_device_pdo_end + "<Eeprom><ByteSize>256</ByteSize></Eeprom>"}}, {}, K::eeprom_removed,
         C::breaking, "Eeprom"},
        {"EepromLarger", {}, {{"<ByteSize>2048</ByteSize>", "<ByteSize>4096</ByteSize>"}}, K::eeprom_size_increased, C::compatible, "Eeprom/ByteSize"},
        {"EepromSmaller", {}, {{"<ByteSize>2048</ByteSize>", "<ByteSize>1024</ByteSize>"}}, K::eeprom_size_decreased, C::breaking, "Eeprom/ByteSize"},
        {"ConfigData", {}, {{"<ConfigData>080E00CC</ConfigData>", "<ConfigData>080E00CD</ConfigData>"}}, K::eeprom_config_data_changed, C::breaking,
         "Eeprom/ConfigData"},
        {"BootStrap", {}, {{"<BootStrap>0010800080108000</BootStrap>", "<BootStrap>0010400080104000</BootStrap>"}}, K::eeprom_boot_strap_changed,
         C::breaking, "Eeprom/BootStrap"},
        {"EepromData", {{second_device_pdo_end, second_device_pdo_end + "<Eeprom><Data>0102</Data></Eeprom>"}},
         {{second_device_pdo_end, second_device_pdo_end + "<Eeprom><Data>0103</Data></Eeprom>"}}, K::eeprom_data_changed, C::breaking, "Eeprom/Data"},
        {"CategoryAdded", {}, {{"<Data>AABB</Data></Category>", "<Data>AABB</Data></Category><Category><CatNo>2</CatNo><Data>CC</Data></Category>"}},
         K::eeprom_category_added, C::compatible, "Eeprom/Category[2]"},
        {"CategoryRemoved", {{"<Data>AABB</Data></Category>", "<Data>AABB</Data></Category><Category><CatNo>2</CatNo><Data>CC</Data></Category>"}}, {},
         K::eeprom_category_removed, C::breaking, "Eeprom/Category[2]"},
        {"CategoryData", {}, {{"<Data>AABB</Data>", "<Data>AABC</Data>"}}, K::eeprom_category_changed, C::breaking, "Eeprom/Category[1]/Data"},
        {"AssignToPdi", {}, {{"<Eeprom>", "<Eeprom AssignToPdi=\"true\">"}}, K::eeprom_attribute_changed, C::breaking, "Eeprom@AssignToPdi"},

        // ---- slots
        {"SlotAdded", {}, {{"</Slots>", "<Slot MinInstances=\"0\" MaxInstances=\"1\"><Name>Second</Name><ModuleIdent>#x00001200</ModuleIdent></Slot></Slots>"}},
         K::slot_added, C::compatible, "Slots/Slot[2]"},
        {"SlotRemoved", {{"</Slots>", "<Slot MinInstances=\"0\" MaxInstances=\"1\"><Name>Second</Name><ModuleIdent>#x00001200</ModuleIdent></Slot></Slots>"}}, {},
         K::slot_removed, C::breaking, "Slots/Slot[2]"},
        {"SlotModuleAdded", {}, {{"<ModuleIdent>#x00001200</ModuleIdent>", "<ModuleIdent>#x00001200</ModuleIdent><ModuleIdent>#x00001300</ModuleIdent>"}},
         K::slot_module_added, C::compatible, "Slots/Slot[1]/ModuleIdent[#x00001300]"},
        {"SlotModuleRemoved", {{"<ModuleIdent>#x00001200</ModuleIdent>", "<ModuleIdent>#x00001200</ModuleIdent><ModuleIdent>#x00001300</ModuleIdent>"}}, {},
         K::slot_module_removed, C::breaking, "Slots/Slot[1]/ModuleIdent[#x00001300]"},
        {"SlotWidened", {}, {{"MaxInstances=\"2\"", "MaxInstances=\"3\""}}, K::slot_instances_widened, C::compatible, "Slots/Slot[1]@MaxInstances"},
        {"SlotNarrowed", {}, {{"MaxInstances=\"2\"", "MaxInstances=\"1\""}}, K::slot_instances_narrowed, C::breaking, "Slots/Slot[1]@MaxInstances"},
        {"SlotIncrement", {}, {{"SlotPdoIncrement=\"1\"", "SlotPdoIncrement=\"2\""}}, K::slot_layout_changed, C::breaking,
         "Slots/Slot[1]@SlotPdoIncrement"},
        {"SlotDefault", {}, {{"<ModuleIdent Default=\"1\">#x00001100</ModuleIdent>", "<ModuleIdent>#x00001100</ModuleIdent>"}},
         K::slot_default_changed, C::compatible, "Slots/Slot[1]/ModuleIdent[#x00001100]@Default"},

        // ---- anything else
        {"UnmodelledXml", {}, {{"<EBusCurrent>120</EBusCurrent>", "<EBusCurrent>200</EBusCurrent>"}}, K::extras_changed, C::cosmetic,
         "Info/Electrical/EBusCurrent"},
        {"TypeAlias", {}, {{"<Name>Output value</Name>\n            <DataType>UINT</DataType>", "<Name>Output value</Name>\n            <DataType>UINT16</DataType>"}},
         K::spelling_changed, C::cosmetic, "RxPdo[#x1600]/Entry[#x7000:00]/DataType"},
    };
}

std::string apply(const Edits& edits) {
    std::string text = diff_base;
    for (const auto& [from, to] : edits) text = edit(text, from, to);
    return text;
}

class ChangeKindTest : public ::testing::TestWithParam<Case> {};

TEST_P(ChangeKindTest, ReportsTheKindWithItsClassAndNothingElse) {
    const Case& c = GetParam();
    const esi::DiffResult r = esi::test::diff_texts(apply(c.old_edits), apply(c.new_edits));
    SCOPED_TRACE(esi::test::describe(r));

    const esi::Change* found = nullptr;
    for (const auto& change : r.changes)
        if (change.kind == c.kind && change.path == c.path) found = &change;
    ASSERT_NE(found, nullptr) << "expected " << esi::to_string(c.kind) << " at " << c.path;
    EXPECT_EQ(found->change_class, c.change_class);
    EXPECT_FALSE(found->message.empty());
    EXPECT_TRUE(found->old_pos.known() || found->new_pos.known()) << "a change points into at least one file";

    const bool revision_error = c.revision_error.value_or(c.change_class == ChangeClass::breaking);
    EXPECT_EQ(esi::test::find_change(r, ChangeKind::revision_not_changed) != nullptr, revision_error);
    for (const auto& change : r.changes) {
        if (change.kind == c.kind || change.kind == ChangeKind::revision_not_changed) continue;
        EXPECT_NE(std::find(c.also.begin(), c.also.end(), change.kind), c.also.end())
            << "unexpected " << esi::to_string(change.kind) << " at " << change.path;
    }
    ChangeClass worst = ChangeClass::cosmetic;
    for (const auto& change : r.changes) worst = std::max(worst, change.change_class);
    EXPECT_EQ(r.verdict, esi::verdict_of(worst));
}

INSTANTIATE_TEST_SUITE_P(Diff, ChangeKindTest, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(ChangeKinds, EveryKindHasAFocusedCase) {
    std::set<ChangeKind> covered;
    for (const auto& c : cases()) covered.insert(c.kind);
    for (const auto& k : esi::change_kinds())
        EXPECT_TRUE(covered.count(k.kind)) << "no focused case for " << k.id;
}

TEST(ChangeKinds, TableRowsAreCompleteAndIdsUnique) {
    std::set<std::string_view> ids;
    for (const auto& k : esi::change_kinds()) {
        EXPECT_TRUE(ids.insert(k.id).second) << "duplicate id " << k.id;
        EXPECT_FALSE(k.reason.empty()) << k.id;
        EXPECT_EQ(esi::info(k.kind).id, k.id);
    }
}

}  // namespace
