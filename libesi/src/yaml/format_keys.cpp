#include "esi/yaml/format_keys.hpp"

#include <array>

namespace esi::yaml {

namespace {

using K = std::string_view;

constexpr K root[] = {"root_element", "esi_version", "vendor", "groups", "devices", "modules", "xml", "descriptions_xml"};
constexpr K vendor[] = {"id",         "name",       "comment",     "url",         "description_url", "image_data",
                        "image_file", "image16x14", "unique_name", "file_version", "xml"};
constexpr K group[] = {"type", "name", "comment", "sort_order", "parent_group", "image_data", "image_file", "image16x14", "xml"};
constexpr K device[] = {"type",       "product_code", "revision",  "serial_no",      "tc_cfg_mode_safe_op", "type_xml",
                        "name",       "comment",      "url",       "group",          "physics",             "invisible",
                        "image_data", "image_file",   "image16x14", "profile",       "objects",             "data_types",
                        "dictionary_xml", "esc",      "eeprom",   "mailbox",   "sms",            "fmmus",               "sync_units",
                        "rxpdo",      "txpdo",        "init",      "dc",             "slots",               "limits",
                        "derive",     "xml"};
constexpr K profile[] = {"number", "add_info", "channel", "dictionary_file", "xml"};
constexpr K eeprom[] = {"size", "config_data", "boot_strap", "data", "categories", "assign_to_pdi", "xml"};
constexpr K boot_strap[] = {"out_address", "out_size", "in_address", "in_size"};
constexpr K eeprom_category[] = {"number", "data", "data_string", "data_uint", "data_udint", "preserve_online_data", "xml"};
constexpr K mailbox[] = {"size", "out_size", "in_size", "out_address", "in_address", "data_link_layer", "real_time_mode",
                         "coe",  "eoe",      "foe",     "soe",         "voe",        "aoe",             "xml"};
constexpr K module_mailbox[] = {"data_link_layer", "real_time_mode", "coe", "eoe", "foe", "soe", "voe", "aoe", "xml"};
constexpr K coe[] = {"sdo_info",      "pdo_assign",     "pdo_config",   "pdo_upload",
                     "complete_access", "segmented_sdo", "diag_history", "sdo_upload_with_max_length",
                     "time_distribution", "module_od",   "eds_file",     "ds402_channels",
                     "xml"};
constexpr K eoe[] = {"ip", "mac", "time_stamp", "init", "xml"};
constexpr K soe[] = {"channel_count", "drive_follows_bit3_support", "init", "xml"};
constexpr K aoe[] = {"ads_router", "generate_own_net_id", "initialize_own_net_id", "init", "xml"};
constexpr K plain_protocol[] = {"xml"};
constexpr K sm[] = {"type",    "address", "control_byte", "size",    "min_size",         "max_size",     "enable",
                    "virtual", "watchdog", "op_only",     "fixed_assignment", "one_byte_mode", "xml"};
constexpr K fmmu[] = {"type", "sm", "su", "op_only", "xml"};
constexpr K sync_unit[] = {"text", "separate_su", "separate_frame", "depend_on_input_state", "frame_repeat_support", "xml"};
constexpr K pdo[] = {"index",          "name",           "fixed",          "mandatory",        "virtual",
                     "sm",             "assigned",       "su",             "exclude",          "excluded_sms",
                     "pdo_order",      "os_fac",         "os_min",         "os_max",           "os_index_inc",
                     "overwritten_by_module", "sra_parameter", "safety_pdo_type", "safety_conn_number",
                     "index_depend_on_slot", "index_depend_on_slot_group", "entries", "xml"};
constexpr K pdo_exclude[] = {"index", "depend_on_slot", "depend_on_slot_group"};
constexpr K pdo_entry[] = {"object", "subindex", "pad",   "bit_len", "name", "comment", "data_type", "dscale", "swap_data",
                           "fixed",  "index_depend_on_slot", "index_depend_on_slot_group", "xml"};
constexpr K init_coe[] = {"transition", "object", "subindex", "value", "data", "comment", "complete_access", "fixed",
                          "overwritten_by_module", "adapt_automatically", "index_depend_on_slot",
                          "index_depend_on_slot_group", "xml"};
constexpr K init_soe[] = {"transition", "idn", "channel", "data", "comment", "fixed", "overwritten_by_module",
                          "adapt_automatically", "xml"};
constexpr K init_eoe[] = {"transition", "type", "data", "comment", "xml"};
constexpr K init_aoe[] = {"transition", "data", "comment", "xml"};
constexpr K dc[] = {"op_modes", "unknown_frmw", "unknown_64bit", "external_ref_clock", "potential_reference_clock",
                    "time_loop_control_only", "xml"};
constexpr K op_mode[] = {"name", "description", "assign_activate", "cycle_time_sync0", "shift_time_sync0",
                         "cycle_time_sync1", "shift_time_sync1", "xml"};
constexpr K dc_time[] = {"value", "factor", "input", "output_delay_time", "input_delay_time"};
// Flags and Info keys shared by objects, generated record entries and DataType sub-items.
#define ESI_FLAG_KEYS "access", "read_restrictions", "write_restrictions", "pdo", "category", "backup", "setting", \
                      "safety_mapping", "attribute", "transition", "sdo_access", "flags_xml"
#define ESI_INFO_KEYS "default", "min", "max", "default_data", "min_data", "max_data", "default_string", "display_name", \
                      "unit", "info_xml"
constexpr K object[] = {"name", "comment", "type", "bit_size", "array", "entries", "enum", ESI_FLAG_KEYS, ESI_INFO_KEYS,
                        "info_sub_items", "index_depend_on_slot", "index_depend_on_slot_group", "index_overwritten_by_module", "xml"};
// Object/Info/SubItem as an ESI file wrote it (the importer's verbatim form): values are untyped.
constexpr K info_sub_item[] = {"name", ESI_INFO_KEYS, "xml"};
constexpr K object_entry[] = {"name", "comment", "type", "bit_size", "bit_offset", ESI_FLAG_KEYS, ESI_INFO_KEYS, "xml"};
constexpr K data_type[] = {"name", "index", "base_type", "bit_size", "comment", "array", "sub_items", "enum", "xml"};
constexpr K array_info[] = {"lower_bound", "elements"};
constexpr K type_sub_item[] = {"subindex", "name",    "display_name", "type",         "comment",        "bit_size",
                               "bit_offset", "default", "min",          "max",          "default_data",   "default_string",
                               ESI_FLAG_KEYS, "xml"};
#undef ESI_FLAG_KEYS
#undef ESI_INFO_KEYS
constexpr K enum_value[] = {"text", "comment"};
constexpr K module[] = {"type",  "ident", "class",   "pdo_group", "type_xml", "name",       "image_data",     "image_file",
                        "image16x14", "rxpdo", "txpdo", "mailbox", "init",  "profile",    "objects",        "data_types",
                        "dictionary_xml", "dc_op_mode", "derive", "xml"};
constexpr K slots[] = {"list",                  "max_slot_count",      "max_slot_group_count",
                       "slot_pdo_increment",    "slot_group_pdo_increment", "slot_index_increment",
                       "slot_group_index_increment", "xml"};
constexpr K slot[] = {"name",           "modules",        "module_classes",   "default",
                      "fallback",       "slot_group",     "min_instances",    "max_instances",
                      "slot_pdo_increment", "slot_group_pdo_increment", "slot_index_increment", "slot_group_index_increment",
                      "image_data",     "image_file",     "image16x14",       "xml"};
constexpr K slot_module[] = {"module", "default"};
constexpr K slot_module_class[] = {"class", "vendor_id", "name", "xml"};
constexpr K derive[] = {"groups",          "mailbox",           "sync_managers",   "fmmus",
                        "pdo_assignment",  "pdo_entries",       "mapping_objects", "assignment_objects",
                        "sm_types_object", "identity_object",   "device_type_object", "data_types"};
constexpr K module_derive[] = {"pdo_entries", "data_types"};
// The keys esi::yaml::read_limits accepts (libesi/src/yaml/limits.cpp), shared with .esi-lint.yaml.
constexpr K limits[] = {"max_pdos",          "pdo_index_ranges", "max_entries_per_pdo", "bitlen",     "fixed_sm",
                        "transitions",       "max_init_cmd_bytes", "max_mailbox_size", "absent_objects", "mailbox_protocols",
                        "max_fmmus",         "max_sms",          "pdo_assign",          "pdo_config", "pdo_names",
                        "parameter_index",   "sync0_cycle"};
constexpr K xml[] = {"attributes", "elements"};
constexpr K xml_element[] = {"after", "xml"};

#define ESI_CONTEXT(name) ContextKeys{Context::name, #name, name}
constexpr std::array contexts{
    ESI_CONTEXT(root),         ESI_CONTEXT(vendor),        ESI_CONTEXT(group),           ESI_CONTEXT(device),
    ESI_CONTEXT(profile),      ESI_CONTEXT(eeprom),        ESI_CONTEXT(boot_strap),      ESI_CONTEXT(eeprom_category),
    ESI_CONTEXT(mailbox),      ESI_CONTEXT(module_mailbox), ESI_CONTEXT(coe),            ESI_CONTEXT(eoe),
    ESI_CONTEXT(soe),          ESI_CONTEXT(aoe),           ESI_CONTEXT(plain_protocol),  ESI_CONTEXT(sm),
    ESI_CONTEXT(fmmu),         ESI_CONTEXT(sync_unit),     ESI_CONTEXT(pdo),             ESI_CONTEXT(pdo_exclude),
    ESI_CONTEXT(pdo_entry),    ESI_CONTEXT(init_coe),      ESI_CONTEXT(init_soe),        ESI_CONTEXT(init_eoe),
    ESI_CONTEXT(init_aoe),     ESI_CONTEXT(dc),            ESI_CONTEXT(op_mode),         ESI_CONTEXT(dc_time),
    ESI_CONTEXT(object),       ESI_CONTEXT(object_entry),  ESI_CONTEXT(data_type),       ESI_CONTEXT(array_info),
    ESI_CONTEXT(type_sub_item), ESI_CONTEXT(enum_value),   ESI_CONTEXT(module),          ESI_CONTEXT(slots),
    ESI_CONTEXT(slot),         ESI_CONTEXT(slot_module),   ESI_CONTEXT(slot_module_class), ESI_CONTEXT(derive),
    ESI_CONTEXT(module_derive), ESI_CONTEXT(limits),       ESI_CONTEXT(xml),             ESI_CONTEXT(xml_element),
    ESI_CONTEXT(info_sub_item),
};
#undef ESI_CONTEXT

}  // namespace

std::span<const ContextKeys> format_contexts() { return contexts; }

const ContextKeys& keys_of(Context context) {
    for (const auto& c : contexts)
        if (c.context == context) return c;
    return contexts.front();
}

}  // namespace esi::yaml
