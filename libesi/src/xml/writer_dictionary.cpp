// ESI writer: Profile and the CoE object dictionary (ProfileType, DictionaryType, DataTypeType,
// SubItemType, EnumInfoType, ObjectType, ObjectInfoType of EtherCATBase.xsd 1.17).

#include "xml/writer_model.hpp"

namespace esi::xml_writer {

namespace {

constexpr std::string_view profile_order[] = {"ProfileNo",   "AddInfo",        "SubAddInfo", "ChannelCount",
                                              "ChannelInfo", "DictionaryFile", "Dictionary", "DiagFile",
                                              "DiagMessages", "VendorSpecific"};
constexpr std::string_view dictionary_order[] = {"UnitTypes", "DataTypes", "Objects"};
constexpr std::string_view data_type_order[] = {"Index",     "Name",    "BaseType", "Comment",    "BitSize",
                                                "ArrayInfo", "SubItem", "EnumInfo", "Properties", "Xml"};
constexpr std::string_view type_sub_item_order[] = {"SubIdx",       "Name",         "DisplayName", "Type",         "Comment",
                                                    "BitSize",      "BitOffs",      "DefaultString", "DefaultData", "MinValue",
                                                    "MaxValue",     "DefaultValue", "Flags",       "Property",     "Xml"};
constexpr std::string_view object_order[] = {"Index", "Name", "Comment", "Type", "BitSize", "Info", "Flags", "Properties", "Xml"};
constexpr std::string_view object_info_order[] = {"DefaultString", "MinData",      "MaxData", "DefaultData", "MinValue",
                                                  "MaxValue",      "DefaultValue", "SubItem", "DisplayName", "Unit"};
constexpr std::string_view info_sub_item_order[] = {"Name", "Info"};
constexpr std::string_view flags_order[] = {"Access",    "Category",   "PdoMapping", "SafetyMapping", "Attribute",
                                            "Transition", "SdoAccess", "Backup",     "Setting"};

void write_flags(XmlEmitter& out, const ObjectFlags& flags) {
    out.begin("Flags");
    write_extra_attributes(out, flags.extras);
    ChildPlacer children(out, flags.extras, flags_order);
    if (flags.access || flags.access_read_restrictions || flags.access_write_restrictions) {
        children.at("Access");
        out.begin("Access");
        put_text(out, "ReadRestrictions", flags.access_read_restrictions);
        put_text(out, "WriteRestrictions", flags.access_write_restrictions);
        if (flags.access) out.text(*flags.access);
        out.end();
    }
    const auto text_leaf = [&](std::string_view element, const auto& value) {
        if (!value) return;
        children.at(element);
        out.leaf(element, *value);
    };
    text_leaf("Category", flags.category);
    text_leaf("PdoMapping", flags.pdo_mapping);
    text_leaf("SafetyMapping", flags.safety_mapping);
    if (flags.attribute) {
        children.at("Attribute");
        out.leaf("Attribute", identity_hex(*flags.attribute).view());
    }
    if (flags.transition) {
        children.at("Transition");
        out.leaf("Transition", *flags.transition);
    }
    if (flags.sdo_access) {
        children.at("SdoAccess");
        out.leaf("SdoAccess", *flags.sdo_access);
    }
    if (flags.backup) {
        children.at("Backup");
        leaf_decimal(out, "Backup", *flags.backup);
    }
    if (flags.setting) {
        children.at("Setting");
        leaf_decimal(out, "Setting", *flags.setting);
    }
    children.finish();
    out.end();
}

// Min/Max/Default values are decimal: one spelling for signed, unsigned and 64-bit values alike.
void write_values(XmlEmitter& out, ChildPlacer& children, const RareOptional<Number>& min, const RareOptional<Number>& max,
                  const RareOptional<Number>& default_value) {
    if (min) {
        children.at("MinValue");
        leaf_decimal(out, "MinValue", *min);
    }
    if (max) {
        children.at("MaxValue");
        leaf_decimal(out, "MaxValue", *max);
    }
    if (default_value) {
        children.at("DefaultValue");
        leaf_decimal(out, "DefaultValue", *default_value);
    }
}

void write_object_info(XmlEmitter& out, const ObjectInfo& info) {
    out.begin("Info");
    write_extra_attributes(out, info.extras);
    ChildPlacer children(out, info.extras, object_info_order);
    if (info.default_string) {
        children.at("DefaultString");
        out.leaf("DefaultString", *info.default_string);
    }
    if (info.min_data) {
        children.at("MinData");
        leaf_hex_data(out, "MinData", *info.min_data);
    }
    if (info.max_data) {
        children.at("MaxData");
        leaf_hex_data(out, "MaxData", *info.max_data);
    }
    if (info.default_data) {
        children.at("DefaultData");
        leaf_hex_data(out, "DefaultData", *info.default_data);
    }
    write_values(out, children, info.min_value, info.max_value, info.default_value);
    for (const auto& sub : info.sub_items) {
        children.at("SubItem");
        out.begin("SubItem");
        ChildPlacer sub_children(out, sub.extras, info_sub_item_order);
        sub_children.at("Name");
        out.leaf("Name", sub.name);
        sub_children.at("Info");  // required by the schema, even when it says nothing
        write_object_info(out, sub.info);
        sub_children.finish();
        out.end();
    }
    if (info.display_name) {
        children.at("DisplayName");
        out.leaf("DisplayName", *info.display_name);
    }
    if (info.unit) {
        children.at("Unit");
        out.leaf("Unit", identity_hex(*info.unit).view());
    }
    children.finish();
    out.end();
}

void write_object(XmlEmitter& out, const Object& object) {
    out.begin("Object");
    write_extra_attributes(out, object.extras);
    ChildPlacer children(out, object.extras, object_order);
    children.at("Index");
    out.begin("Index");
    put_bool(out, "DependOnSlot", object.index_depend_on_slot);
    put_bool(out, "DependOnSlotGroup", object.index_depend_on_slot_group);
    put_bool(out, "OverwrittenByModule", object.index_overwritten_by_module);
    out.text(index_hex(object.index).view());
    out.end();
    write_names(out, children, "Name", object.names);
    write_names(out, children, "Comment", object.comments);
    children.at("Type");
    out.leaf("Type", object.type);
    children.at("BitSize");
    leaf_decimal(out, "BitSize", object.bit_size);
    if (object.info) {
        children.at("Info");
        write_object_info(out, *object.info);
    }
    if (object.flags) {
        children.at("Flags");
        write_flags(out, *object.flags);
    }
    children.finish();
    out.end();
}

void write_type_sub_item(XmlEmitter& out, const DataTypeSubItem& item) {
    out.begin("SubItem");
    write_extra_attributes(out, item.extras);
    ChildPlacer children(out, item.extras, type_sub_item_order);
    if (item.subindex) {
        children.at("SubIdx");
        leaf_decimal(out, "SubIdx", *item.subindex);
    }
    children.at("Name");
    out.leaf("Name", item.name);
    write_names(out, children, "DisplayName", item.display_names);
    children.at("Type");
    out.leaf("Type", item.type);
    write_names(out, children, "Comment", item.comments);
    children.at("BitSize");
    leaf_decimal(out, "BitSize", item.bit_size);
    children.at("BitOffs");
    leaf_decimal(out, "BitOffs", item.bit_offset);
    if (item.default_string) {
        children.at("DefaultString");
        out.leaf("DefaultString", *item.default_string);
    }
    if (item.default_data) {
        children.at("DefaultData");
        leaf_hex_data(out, "DefaultData", *item.default_data);
    }
    write_values(out, children, item.min_value, item.max_value, item.default_value);
    if (item.flags) {
        children.at("Flags");
        write_flags(out, *item.flags);
    }
    children.finish();
    out.end();
}

void write_data_type(XmlEmitter& out, const DataType& type) {
    out.begin("DataType");
    write_extra_attributes(out, type.extras);
    ChildPlacer children(out, type.extras, data_type_order);
    if (type.index) {
        children.at("Index");
        out.leaf("Index", index_hex(*type.index).view());
    }
    children.at("Name");
    out.leaf("Name", type.name);
    if (type.base_type) {
        children.at("BaseType");
        out.leaf("BaseType", *type.base_type);
    }
    write_names(out, children, "Comment", type.comments);
    children.at("BitSize");
    leaf_decimal(out, "BitSize", type.bit_size);
    for (const auto& array : type.array_info) {
        children.at("ArrayInfo");
        out.begin("ArrayInfo");
        leaf_decimal(out, "LBound", array.lower_bound);
        leaf_decimal(out, "Elements", array.elements);
        out.end();
    }
    for (const auto& item : type.sub_items) {
        children.at("SubItem");
        write_type_sub_item(out, item);
    }
    for (const auto& value : type.enums) {
        children.at("EnumInfo");
        out.begin("EnumInfo");
        for (const auto& text : value.texts) write_localized(out, "Text", text);
        leaf_decimal(out, "Enum", value.value);
        for (const auto& comment : value.comments) write_localized(out, "Comment", comment);
        out.end();
    }
    children.finish();
    out.end();
}

}  // namespace

void write_dictionary(XmlEmitter& out, const Dictionary& dictionary) {
    out.begin("Dictionary");
    write_extra_attributes(out, dictionary.extras);
    ChildPlacer children(out, dictionary.extras, dictionary_order);
    if (!dictionary.data_types.empty()) {
        children.at("DataTypes");
        out.begin("DataTypes");
        for (const auto& type : dictionary.data_types) write_data_type(out, type);
        out.end();
    }
    children.at("Objects");  // required by the schema, even when empty
    out.begin("Objects");
    for (const auto& object : dictionary.objects) write_object(out, object);
    out.end();
    children.finish();
    out.end();
}

void write_profile(XmlEmitter& out, const Profile& profile) {
    out.begin("Profile");
    put_decimal(out, "Channel", profile.channel);
    write_extra_attributes(out, profile.extras);
    ChildPlacer children(out, profile.extras, profile_order);
    if (profile.profile_no) {
        children.at("ProfileNo");
        leaf_decimal(out, "ProfileNo", *profile.profile_no);
    }
    if (profile.add_info) {
        children.at("AddInfo");
        leaf_decimal(out, "AddInfo", *profile.add_info);
    }
    if (profile.dictionary_file) {
        children.at("DictionaryFile");
        out.leaf("DictionaryFile", *profile.dictionary_file);
    }
    if (profile.dictionary) {
        children.at("Dictionary");
        write_dictionary(out, *profile.dictionary);
    }
    children.finish();
    out.end();
}

}  // namespace esi::xml_writer
