#pragma once
// Profile/Dictionary: data types and objects of the CoE object dictionary.

#include "esi/model/common.hpp"
#include "esi/model/rare_optional.hpp"
#include "esi/number.hpp"

namespace esi {

// Absent fields that are rare in vendor files are RareOptional: a dictionary holds tens of
// thousands of Flags, Info and SubItem elements, and the model's size is mostly theirs.
struct ObjectFlags {
    std::optional<std::string> access;  // ro, rw, wo
    RareOptional<std::string> access_read_restrictions;
    RareOptional<std::string> access_write_restrictions;
    std::optional<std::string> category;     // m, o, c
    RareOptional<std::string> pdo_mapping;  // R, T, RT, TR
    RareOptional<std::string> safety_mapping;
    std::optional<std::uint32_t> attribute;
    RareOptional<std::string> transition;
    RareOptional<std::string> sdo_access;
    std::optional<std::int32_t> backup;
    std::optional<std::int32_t> setting;
    SourcePos pos;
    Extras extras;
};

struct ObjectSubItemInfo;

// ObjectInfoType: default and limit values of an object or of one of its sub-items.
struct ObjectInfo {
    RareOptional<std::string> default_string;
    RareOptional<HexData> min_data;
    RareOptional<HexData> max_data;
    std::optional<HexData> default_data;
    RareOptional<Number> min_value;
    RareOptional<Number> max_value;
    RareOptional<Number> default_value;
    std::vector<ObjectSubItemInfo> sub_items;
    RareOptional<std::string> display_name;
    std::optional<std::uint32_t> unit;
    SourcePos pos;
    Extras extras;
};

// Object/Info/SubItem: values for one sub-entry, matched to the type's SubItem by Name.
struct ObjectSubItemInfo {
    std::string name;
    ObjectInfo info;
    SourcePos pos;
    Extras extras;
};

struct Object {
    std::uint32_t index = 0;
    SourcePos index_pos;
    // Index@DependOnSlot / @DependOnSlotGroup / @OverwrittenByModule: in module dictionaries the
    // index moves with the slot (ETG.2000 ObjectType; modular devices, ETG.2001).
    std::optional<bool> index_depend_on_slot;
    std::optional<bool> index_depend_on_slot_group;
    std::optional<bool> index_overwritten_by_module;
    Names names;
    Names comments;
    std::string type;  // a DataType name (basic or defined in DataTypes)
    SourcePos type_pos;
    std::uint64_t bit_size = 0;
    SourcePos bit_size_pos;
    std::optional<ObjectInfo> info;
    std::optional<ObjectFlags> flags;
    SourcePos pos;
    Extras extras;  // Properties, Xml
};

struct ArrayInfo {
    std::int64_t lower_bound = 0;
    std::int64_t elements = 0;
    SourcePos pos;
};

struct DataTypeSubItem {
    std::optional<std::uint32_t> subindex;  // SubIdx
    std::string name;
    Names display_names;
    std::string type;
    Names comments;
    std::uint64_t bit_size = 0;
    std::uint64_t bit_offset = 0;  // BitOffs
    RareOptional<std::string> default_string;
    std::optional<HexData> default_data;
    RareOptional<Number> min_value;
    RareOptional<Number> max_value;
    RareOptional<Number> default_value;
    std::optional<ObjectFlags> flags;
    SourcePos pos;
    Extras extras;
};

struct EnumValue {
    Names texts;
    Number value;
    Names comments;
    SourcePos pos;
};

struct DataType {
    std::optional<std::uint32_t> index;
    std::string name;
    SourcePos name_pos;
    std::optional<std::string> base_type;
    Names comments;
    std::uint64_t bit_size = 0;
    std::vector<ArrayInfo> array_info;
    std::vector<DataTypeSubItem> sub_items;
    std::vector<EnumValue> enums;
    SourcePos pos;
    Extras extras;  // Properties, Xml
};

struct Dictionary {
    std::vector<DataType> data_types;
    std::vector<Object> objects;
    SourcePos pos;
    Extras extras;  // UnitTypes

    [[nodiscard]] const Object* find_object(std::uint32_t index) const;
    [[nodiscard]] const DataType* find_data_type(std::string_view name) const;
};

struct Profile {
    std::optional<std::int32_t> profile_no;
    std::optional<std::int32_t> add_info;
    std::optional<std::int32_t> channel;  // @Channel (deprecated, CTT 5-6)
    std::optional<std::string> dictionary_file;
    std::optional<Dictionary> dictionary;
    SourcePos pos;
    Extras extras;  // ChannelCount, ChannelInfo, DiagFile, DiagMessages, VendorSpecific …
};

}  // namespace esi
