#pragma once
// The keys of every mapping in the YAML device source, one table per context. The front end
// checks mappings against these tables (unknown key -> did-you-mean), and a test checks that
// schemas/esi-device.schema.json declares exactly these keys, so parser, schema and
// docs/yaml-format.md cannot drift apart.

#include <span>
#include <string_view>

namespace esi::yaml {

enum class Context {
    root,
    vendor,
    group,
    device,
    profile,
    eeprom,
    boot_strap,
    eeprom_category,
    mailbox,
    module_mailbox,
    coe,
    eoe,
    soe,
    aoe,
    plain_protocol,
    sm,
    fmmu,
    sync_unit,
    pdo,
    pdo_exclude,
    pdo_entry,
    init_coe,
    init_soe,
    init_eoe,
    init_aoe,
    dc,
    op_mode,
    dc_time,
    object,
    object_entry,
    data_type,
    array_info,
    type_sub_item,
    enum_value,
    module,
    slots,
    slot,
    slot_module,
    slot_module_class,
    derive,
    module_derive,
    limits,
    xml,
    xml_element,
    info_sub_item,
};

struct ContextKeys {
    Context context;
    std::string_view name;  // the $defs name in the JSON Schema
    std::span<const std::string_view> keys;
};

[[nodiscard]] std::span<const ContextKeys> format_contexts();
[[nodiscard]] const ContextKeys& keys_of(Context context);

}  // namespace esi::yaml
